// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.api;

import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.function.Function;
import java.util.stream.Collectors;

/**
 * Every setting of the core, each declared once with its type, default and meaning. The node
 * declares one ROS parameter per setting from the catalogue ({@code --catalogue}), so names,
 * types and defaults cannot drift; the core refuses a key it does not know, so a misspelt one
 * never silently leaves the default in force.
 */
public enum Setting {
    DEFAULT_REASONER("default_reasoner", Type.STRING, "PELLET",
            "reasoner used when LOAD or CREATE names none (PELLET is Openllet: SWRL built-ins included)"),
    FULL_ENTITY_IRI("full_entity_iri", Type.BOOLEAN, true,
            "answer entities as full IRIs in angle brackets (true) or as short names (false)"),
    ALLOWED_DIRS("allowed_dirs", Type.STRING_ARRAY, List.of(),
            "what a client may make the core read: LOAD FILE paths, PDDL mapping files and every document an"
                    + " owl:imports resolves to must lie inside these (never state_dir, nor a hidden file or folder"
                    + " below them)"),
    WRITE_DIRS("write_dirs", Type.STRING_ARRAY, List.of(),
            "what a client may make the core write: SAVE, SAVE INFERENCE, SAVE PDDL PROBLEM and LOG FILE ON paths"
                    + " must lie inside these; never hidden paths, files directly in the home, working or temp"
                    + " directory, the installation, plugin_dirs or state_dir (docs/security.md)"),
    PROTECTED_DIRS("protected_dirs", Type.STRING_ARRAY, List.of(),
            "more directories no directive may write into, besides those never written whatever the settings"
                    + " say (docs/security.md)"),
    WEB_LOADING("web_loading", Type.BOOLEAN, false,
            "allow LOAD WEB and owl:imports from the web; off, the core opens no network connection"),
    IGNORE_MISSING_IMPORTS("ignore_missing_imports", Type.BOOLEAN, false,
            "load an ontology whose owl:imports cannot be resolved, listing them in error_description"
                    + " (default: refuse, 222)"),
    SPARQL_TIMEOUT_MS("sparql_timeout_ms", Type.INTEGER, 30_000L,
            "default time limit of a SPARQL query, and the most one may ask for (0 = none)"),
    SPARQL_FEDERATED("sparql_federated", Type.BOOLEAN, false,
            "let SPARQL SERVICE clauses query other endpoints (opens network connections; else 223)"),
    STRICT_NAMES("strict_names", Type.BOOLEAN, false,
            "a QUERY naming an entity the reference does not know answers 224 instead of an empty list"
                    + " (other commands create it, as in ARMOR)"),
    LOCK_WAIT_MS("lock_wait_ms", Type.INTEGER, 30_000L,
            "longest wait for a reference another directive is using (then 211, timeout=true)"),
    // As long as a directive waits for a busy reference (lock_wait_ms): no question holds a
    // reference for longer than others are willing to wait for it (docs/security.md).
    REASONER_TIMEOUT_MS("reasoner_timeout_ms", Type.INTEGER, 30_000L,
            "time limit of one directive's reasoner work (then 211, timeout=true, within 1 s more) (0 = none)"),
    REFERENCES_PER_CLIENT("references_per_client", Type.INTEGER, 100L,
            "most references one client_name may have made (LOAD, CREATE) and not dropped; then 226 (0 = no"
                    + " limit)"),
    MOUNT_LEASE_S("mount_lease_s", Type.INTEGER, 0L,
            "release a mount whose holder sent nothing for this long (0 = never)"),
    STATE_DIR("state_dir", Type.STRING, "", "journals and checkpoints of every reference"),
    RESTORE_STATE("restore_state", Type.BOOLEAN, true,
            "restore the references found in state_dir at start; false deletes them for a clean start"),
    JOURNAL_FSYNC("journal_fsync", Type.BOOLEAN, true,
            "force every journal record to disk before acknowledging (survives power loss, not only a crash)"),
    CHECKPOINT_EVERY_CHANGES("checkpoint_every_changes", Type.INTEGER, 1000L,
            "checkpoint a reference after this many journal records"),
    CHECKPOINT_EVERY_S("checkpoint_every_s", Type.INTEGER, 60L,
            "... or when it changed and its checkpoint is this old"),
    PLUGIN_DIRS("plugin_dirs", Type.STRING_ARRAY, List.of(),
            "directories whose jars add command groups and reasoner factories (docs/extending.md)"),
    PLUGIN_TIMEOUT_MS("plugin_timeout_ms", Type.INTEGER, 60_000L,
            "time limit of a plugin's command: then it is stopped, its changes undone, 211 (0 = none)");

    /** The types a setting can have; JSON and ROS parameters both have them. */
    public enum Type {
        BOOLEAN, INTEGER, DOUBLE, STRING, STRING_ARRAY;

        public String catalogueName() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    private static final Map<String, Setting> BY_KEY = Arrays.stream(values())
            .collect(Collectors.toMap(Setting::key, Function.identity()));

    private final String key;
    private final Type type;
    private final Object defaultValue;
    private final String description;

    Setting(String key, Type type, Object defaultValue, String description) {
        this.key = key;
        this.type = type;
        this.defaultValue = defaultValue;
        this.description = description;
    }

    public static Optional<Setting> byKey(String key) {
        return Optional.ofNullable(BY_KEY.get(key));
    }

    public String key() {
        return key;
    }

    public Type type() {
        return type;
    }

    /** A Boolean, Long, Double, String or List of String, as {@link #type()} says. */
    public Object defaultValue() {
        return defaultValue;
    }

    public String description() {
        return description;
    }

    /**
     * Whether a change while the core runs takes effect. None does yet: the core reads its
     * settings once, at start, so the node declares every one of them read-only.
     */
    public boolean live() {
        return false;
    }
}
