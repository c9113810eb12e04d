// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Settings fixed when the core starts. The ROS node declares a parameter of the same name for
 * each and hands them over at start-up; the core never reads ROS parameters itself.
 *
 * @param fullEntityIri    answer entities as {@code <full IRI>} (true) or by their short name
 * @param defaultReasoner  reasoner used when a LOAD or CREATE names none
 * @param allowedDirs      what a client may make the core read (LOAD FILE, mappings, imports) lies inside these
 * @param webLoading       whether LOAD WEB may fetch a URL
 * @param lockWaitMs       how long a directive waits for a reference another directive is using
 * @param reasonerTimeoutMs time limit handed to the reasoners (0 = none)
 * @param mountLeaseS      a mount whose holder sent nothing for this long is released (0 = never)
 * @param durability       where and how acknowledged changes are kept across restarts
 * @param safeguards       what a directive may reach and spend beyond its reference
 * @param writing          where a directive may write (SAVE, LOG FILE), and what it never may
 */
public record CoreConfig(
        boolean fullEntityIri,
        String defaultReasoner,
        List<Path> allowedDirs,
        boolean webLoading,
        long lockWaitMs,
        long reasonerTimeoutMs,
        long mountLeaseS,
        Durability durability,
        Safeguards safeguards,
        Writing writing) {

    /**
     * Journal and checkpoint settings.
     *
     * @param stateDir               root of the per-reference journals; null keeps nothing on disk
     * @param restore                load the state found at start (false: delete it, start clean)
     * @param fsync                  force each journal record to the disk before acknowledging
     * @param checkpointEveryChanges checkpoint a reference after this many journal records
     * @param checkpointEverySeconds ... or when its last checkpoint is this old and it changed since
     */
    public record Durability(Path stateDir, boolean restore, boolean fsync, int checkpointEveryChanges,
                             long checkpointEverySeconds) {
        public static final Durability NONE = new Durability(null, false, false,
                ((Long) Setting.CHECKPOINT_EVERY_CHANGES.defaultValue()).intValue(),
                (Long) Setting.CHECKPOINT_EVERY_S.defaultValue());
    }

    /**
     * Limits on what a directive may reach (imports, SPARQL endpoints) and spend (SPARQL time).
     *
     * @param sparqlTimeoutMs      default time limit of a SPARQL query, and the most a query may ask for (0 = none)
     * @param sparqlFederated      let SPARQL SERVICE clauses query remote endpoints (opens network connections)
     * @param ignoreMissingImports load an ontology whose imports cannot be resolved, listing them in the answer
     * @param strictNames          a QUERY naming an entity the reference does not know is an error (224),
     *                             not an empty answer
     * @param pluginTimeoutMs      time limit of one command of a plugin (0 = none)
     * @param referencesPerClient  most references one client may have made and not dropped (0 = no limit)
     */
    public record Safeguards(long sparqlTimeoutMs, boolean sparqlFederated, boolean ignoreMissingImports,
                             boolean strictNames, long pluginTimeoutMs, long referencesPerClient) {
        public static final Safeguards DEFAULT = new Safeguards((Long) Setting.SPARQL_TIMEOUT_MS.defaultValue(),
                (Boolean) Setting.SPARQL_FEDERATED.defaultValue(),
                (Boolean) Setting.IGNORE_MISSING_IMPORTS.defaultValue(), (Boolean) Setting.STRICT_NAMES.defaultValue());

        public Safeguards(long sparqlTimeoutMs, boolean sparqlFederated, boolean ignoreMissingImports,
                          boolean strictNames, long pluginTimeoutMs) {
            this(sparqlTimeoutMs, sparqlFederated, ignoreMissingImports, strictNames, pluginTimeoutMs,
                    (Long) Setting.REFERENCES_PER_CLIENT.defaultValue());
        }

        public Safeguards(long sparqlTimeoutMs, boolean sparqlFederated, boolean ignoreMissingImports,
                          boolean strictNames) {
            this(sparqlTimeoutMs, sparqlFederated, ignoreMissingImports, strictNames,
                    (Long) Setting.PLUGIN_TIMEOUT_MS.defaultValue());
        }

        public Safeguards(long sparqlTimeoutMs, boolean sparqlFederated, boolean ignoreMissingImports) {
            this(sparqlTimeoutMs, sparqlFederated, ignoreMissingImports, false);
        }
    }

    /**
     * What a client may make the core write: files inside {@code writeDirs}, never inside
     * {@code protectedDirs} or {@code pluginDirs} (nor the state directory, hidden paths and the
     * other places {@code WritablePaths} names).
     *
     * @param writeDirs     SAVE, SAVE INFERENCE, SAVE PDDL PROBLEM and LOG FILE paths lie inside these
     * @param protectedDirs never written, whatever writeDirs say (the installation, as the node finds it)
     * @param pluginDirs    the plugin directories, never written either
     */
    public record Writing(List<Path> writeDirs, List<Path> protectedDirs, List<Path> pluginDirs) {
        /** Nothing is writable. */
        public static final Writing NONE = new Writing(List.of(), List.of(), List.of());

        public Writing {
            writeDirs = List.copyOf(writeDirs);
            protectedDirs = List.copyOf(protectedDirs);
            pluginDirs = List.copyOf(pluginDirs);
        }

        /** Writes allowed inside these directories only. */
        public static Writing into(Path... writeDirs) {
            return new Writing(List.of(writeDirs), List.of(), List.of());
        }
    }

    /** Settings where nothing is writable: the confinement of every embedding and most tests. */
    public CoreConfig(boolean fullEntityIri, String defaultReasoner, List<Path> allowedDirs, boolean webLoading,
                      long lockWaitMs, long reasonerTimeoutMs, long mountLeaseS, Durability durability,
                      Safeguards safeguards) {
        this(fullEntityIri, defaultReasoner, allowedDirs, webLoading, lockWaitMs, reasonerTimeoutMs, mountLeaseS,
                durability, safeguards, Writing.NONE);
    }

    /** The same settings, writing allowed as {@code writing} says. */
    public CoreConfig withWriting(Writing writing) {
        return new CoreConfig(fullEntityIri, defaultReasoner, allowedDirs, webLoading, lockWaitMs, reasonerTimeoutMs,
                mountLeaseS, durability, safeguards, writing);
    }

    /** Settings with the default safeguards. */
    public CoreConfig(boolean fullEntityIri, String defaultReasoner, List<Path> allowedDirs, boolean webLoading,
                      long lockWaitMs, long reasonerTimeoutMs, long mountLeaseS, Durability durability) {
        this(fullEntityIri, defaultReasoner, allowedDirs, webLoading, lockWaitMs, reasonerTimeoutMs, mountLeaseS,
                durability, Safeguards.DEFAULT);
    }

    public CoreConfig {
        allowedDirs = List.copyOf(allowedDirs);
        safeguards = safeguards == null ? Safeguards.DEFAULT : safeguards;
        writing = writing == null ? Writing.NONE : writing;
        defaultReasoner = defaultReasoner == null || defaultReasoner.isBlank() ? "PELLET" : defaultReasoner;
    }

    /** The configuration the values of every {@link Setting} make (an empty state_dir keeps nothing). */
    @SuppressWarnings("unchecked")
    public static CoreConfig fromSettings(Map<Setting, Object> values) {
        String stateDir = (String) values.get(Setting.STATE_DIR);
        Durability durability = stateDir.isBlank() ? Durability.NONE : new Durability(Path.of(stateDir),
                (Boolean) values.get(Setting.RESTORE_STATE), (Boolean) values.get(Setting.JOURNAL_FSYNC),
                Math.toIntExact((Long) values.get(Setting.CHECKPOINT_EVERY_CHANGES)),
                (Long) values.get(Setting.CHECKPOINT_EVERY_S));
        return new CoreConfig(
                (Boolean) values.get(Setting.FULL_ENTITY_IRI),
                (String) values.get(Setting.DEFAULT_REASONER),
                paths(values.get(Setting.ALLOWED_DIRS)),
                (Boolean) values.get(Setting.WEB_LOADING),
                (Long) values.get(Setting.LOCK_WAIT_MS),
                (Long) values.get(Setting.REASONER_TIMEOUT_MS),
                (Long) values.get(Setting.MOUNT_LEASE_S),
                durability,
                new Safeguards((Long) values.get(Setting.SPARQL_TIMEOUT_MS),
                        (Boolean) values.get(Setting.SPARQL_FEDERATED),
                        (Boolean) values.get(Setting.IGNORE_MISSING_IMPORTS),
                        (Boolean) values.get(Setting.STRICT_NAMES),
                        (Long) values.get(Setting.PLUGIN_TIMEOUT_MS),
                        (Long) values.get(Setting.REFERENCES_PER_CLIENT)),
                new Writing(paths(values.get(Setting.WRITE_DIRS)), paths(values.get(Setting.PROTECTED_DIRS)),
                        paths(values.get(Setting.PLUGIN_DIRS))));
    }

    @SuppressWarnings("unchecked")
    private static List<Path> paths(Object strings) {
        return ((List<String>) strings).stream().filter(s -> !s.isBlank()).map(Path::of).toList();
    }

    /** Settings for tests and embedding: full IRIs, Openllet, the given directories, generous waits. */
    public static CoreConfig defaults(Path... allowedDirs) {
        return new CoreConfig(true, "PELLET", List.of(allowedDirs), false, 30_000, 0, 0, Durability.NONE);
    }
}
