// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command.builtin;

import io.github.armor.core.answers.Inferences;
import io.github.armor.core.api.AcknowledgedChange;
import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.command.Catalogue;
import io.github.armor.core.command.CommandContext;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.reference.ChangeHistory;
import io.github.armor.core.reference.LoadProgress;
import io.github.armor.core.reference.OntologyFiles;
import io.github.armor.core.reference.ReasonerRegistry;
import io.github.armor.core.reference.Reference;
import io.github.armor.core.reference.WritablePaths;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.function.BiFunction;
import java.util.function.Function;

/** Contract 5.1: creating, saving and dropping references, mounting, and the utilities. */
public final class ReferenceCommands implements CommandGroup {
    @Override
    public void register(CommandTable table) {
        for (String mode : List.of("-", "MOUNTED")) {
            boolean mount = mode.equals("MOUNTED");
            registerLoad(table, "LOAD FILE " + mode, "path", mount, mount ? "load a file and mount the caller on it"
                    : "create the reference from a local ontology file", OntologyFiles::loadFile);
            registerLoad(table, "LOAD WEB " + mode, "URL", mount, mount ? "load from a URL and mount the caller on it"
                    : "create the reference from a URL (web_loading:=true only)", OntologyFiles::loadWeb);
        }
        table.command("CREATE")
                .args("ontology IRI", "buffered manipulation", "reasoner", "buffered reasoner")
                .summary("create the reference as an empty ontology")
                .creating(c -> load(c, -1, false, null,
                        ignored -> new OntologyFiles.Loaded(files(c).create(c.arg(0)), "")));
        table.command("SAVE").optional("path", "format").emptySurplusIgnored()
                .summary("write the ontology to a file").onReference(c -> save(c, false));
        table.command("SAVE INFERENCE").optional("path", "format").emptySurplusIgnored()
                .summary("write the ontology and its inferences to a file").onReference(c -> save(c, true));
        table.command("DROP").emptySurplusIgnored().summary("unload the reference").dropping(c -> {
            c.references().remove(c.reference());
            return Response.ok(true, List.of());
        });
        table.command("MOUNT").emptySurplusIgnored().summary("become the only client allowed to change it")
                .mounting(ReferenceCommands::mount);
        table.command("UNMOUNT").emptySurplusIgnored().summary("release the mount")
                .mounting(ReferenceCommands::unmount);
        table.command("GET ALL REFS").emptySurplusIgnored()
                .summary("names of the loaded references").global(c -> Response.ok(true, c.references().names()));
        // One line per LOAD in flight: reference, phase, bytes read, bytes in all, elapsed ms.
        table.command("GET LOAD PROGRESS").summary("the LOADs in flight, one line each")
                .global(c -> Response.ok(true, LoadProgress.running()));
        table.command("GET CATALOGUE").summary("the catalogue: commands (plugins' too), exit codes, settings; JSON")
                .global(c -> Response.ok(true, List.of(Catalogue.json(c.commands()).toString())));
        table.command("GET STATE DAMAGE").summary("what the state directory could not restore or cannot keep now,"
                + " one JSON object each; empty when nothing").global(c -> Response.ok(true, c.stateDamage()));
        table.command("GET REF CLIENT").optional("reference name").emptySurplusIgnored()
                .summary("the client that holds the mount, if any").global(c -> {
            String holder = named(c).mountedBy();
            return Response.ok(true, holder.isEmpty() ? List.of() : List.of(holder));
        });
        table.command("GET REF REVISION").optional("reference name")
                .summary("the revision: how many changes it has acknowledged").global(c -> Response.ok(true,
                        List.of(Long.toString(named(c).revision()))));
        table.command("GET REF DIGEST").optional("reference name")
                .summary("a SHA-256 of its asserted axioms, annotations and imports: equal for equal ontologies")
                .global(c -> Response.ok(true, List.of(digest(named(c), c.config().lockWaitMs()))));
        table.command("GET REF CHANGES").optional("reference name", "since revision", "client name")
                .summary("its latest acknowledged changes after a revision, one JSON object each")
                .global(ReferenceCommands::changes);
        for (String state : List.of("ON", "OFF")) {
            boolean on = state.equals("ON");
            table.command("LOG SCREEN " + state).emptySurplusIgnored()
                    .summary(on ? "log directives on the node's screen" : "stop logging to the screen").global(c -> {
                c.log().screen(on);
                return Response.ok(true, List.of());
            });
        }
        table.command("LOG FILE ON").args("path").emptySurplusIgnored()
                .summary("log directives to a file").global(c -> {
            WritablePaths writable = WritablePaths.of(c.config());
            c.log().file(writable.openLog(writable.check(c.arg(0))));
            return Response.ok(true, List.of());
        });
        table.command("LOG FILE OFF").emptySurplusIgnored().summary("stop logging to a file").global(c -> {
            c.log().closeFile();
            return Response.ok(true, List.of());
        });
        table.command("APPLY").emptySurplusIgnored().summary("apply the buffered manipulations").manipulation(c -> {
            c.reference().applyPending();
            return c.ok();
        });
        table.command("REASON").emptySurplusIgnored()
                .summary("apply the buffer and update the reasoner").manipulation(c -> {
            // Replayed, a REASON only applies: the restored reasoner is brought up to date once, at the end.
            if (c.replaying()) {
                c.reference().applyPending();
            } else {
                c.reference().reason();
            }
            return c.ok();
        });
    }

    /**
     * What tells two states of an ontology apart without saving it: the sorted text of its
     * axioms, annotations and imports, hashed (a fuzz run checks rejected directives with it).
     */
    private static String digest(Reference reference, long lockWaitMs) {
        List<String> lines = reference.locked(lockWaitMs, r -> {
            List<String> all = new java.util.ArrayList<>();
            r.ontology().axioms().forEach(a -> all.add(a.toString()));
            r.ontology().annotations().forEach(a -> all.add("annotation " + a));
            r.ontology().importsDeclarations().forEach(i -> all.add("import " + i.getIRI()));
            all.add("id " + r.ontology().getOntologyID());
            return all;
        });
        java.util.Collections.sort(lines);
        try {
            java.security.MessageDigest sha = java.security.MessageDigest.getInstance("SHA-256");
            for (String line : lines) {
                sha.update(line.getBytes(java.nio.charset.StandardCharsets.UTF_8));
                sha.update((byte) '\n');
            }
            return java.util.HexFormat.of().formatHex(sha.digest());
        } catch (java.security.NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }

    /** The reference a utility names in its first argument, or the directive's. */
    private static Reference named(CommandContext c) {
        return c.references().get(c.hasArg(0) ? c.arg(0) : c.directive().referenceName());
    }

    /**
     * What lets a client whose answer was lost (216, 211 from the node, a lost reply) learn
     * whether its change was applied before it sends it again: the kept changes after a
     * revision, oldest first; the description says when older ones are no longer kept.
     */
    private static Response changes(CommandContext c) {
        Reference reference = named(c);
        long since = -1;
        if (c.hasArg(1)) {
            try {
                since = Long.parseLong(c.arg(1).trim());
            } catch (NumberFormatException e) {
                throw new ArmorException(ExitCode.BAD_DATA_TYPE, "GET REF CHANGES: the revision must be a whole"
                        + " number, got '" + c.arg(1) + "'");
            }
        }
        ChangeHistory history = reference.changeHistory();
        String client = c.hasArg(2) ? c.arg(2) : "";
        List<AcknowledgedChange> after = history.since(since).stream()
                .filter(change -> client.isEmpty() || change.directives().stream()
                        .anyMatch(d -> d.clientName().equals(client)))
                .toList();
        // Revision 0 is the reference as made: its first change is revision 1.
        long wanted = Math.max(since + 1, 1);
        long keptFrom = history.oldestRevision() < 0 ? reference.revision() + 1 : history.oldestRevision();
        List<String> notes = new java.util.ArrayList<>();
        if (keptFrom > wanted) {
            notes.add("changes from revision " + wanted + " to " + (keptFrom - 1)
                    + " are no longer kept; the answer starts at revision " + keptFrom);
        }
        // One answer is bounded, whatever range is asked: the client asks again for the rest.
        List<String> page = new java.util.ArrayList<>();
        long text = 0;
        for (AcknowledgedChange change : after) {
            String json = change.toJson().toString();
            if (!page.isEmpty() && (page.size() >= ChangeHistory.PAGE_CHANGES
                    || text + json.length() > ChangeHistory.PAGE_TEXT)) {
                long last = after.get(page.size() - 1).revision();
                notes.add(ChangeHistory.MORE_AFTER + last + " (one answer holds at most "
                        + ChangeHistory.PAGE_CHANGES + " changes or " + ChangeHistory.PAGE_TEXT
                        + " characters): ask again from revision " + last + " for the rest");
                break;
            }
            page.add(json);
            text += json.length();
        }
        return Response.ok(true, page).withDescription(String.join("; ", notes));
    }

    private static OntologyFiles files(CommandContext c) {
        return new OntologyFiles(c.config());
    }

    /** LOAD FILE and LOAD WEB, plain or MOUNTED: the same arguments after the source, read by {@code reader}. */
    private static void registerLoad(CommandTable table, String key, String source, boolean mount, String summary,
                                     BiFunction<OntologyFiles, String, OntologyFiles.Loaded> reader) {
        table.command(key).args(source, "ontology IRI", "buffered manipulation", "reasoner", "buffered reasoner")
                .emptySurplusIgnored()
                .summary(summary)
                .creating(c -> load(c, 0, mount, c.arg(0), path -> reader.apply(files(c), path)));
    }

    /**
     * LOAD and CREATE share their last four arguments: ontology IRI, buffered manipulation,
     * reasoner, buffered reasoner; {@code first} is the index before them (-1 for CREATE).
     */
    private static Response load(CommandContext c, int first, boolean mount, String source,
                                 Function<String, OntologyFiles.Loaded> reader) {
        String iriArgument = c.arg(first + 1).trim();
        boolean bufferedManipulation = c.flag(first + 2);
        String reasoner = ReasonerRegistry.canonicalName(c.arg(first + 3), c.config().defaultReasoner());
        boolean bufferedReasoner = c.flag(first + 4);
        String name = c.directive().referenceName();
        String client = c.directive().clientName();
        Reference.Settings settings = new Reference.Settings(source, iriArgument, reasoner, bufferedManipulation,
                bufferedReasoner);
        StringBuilder warnings = new StringBuilder();
        Reference reference = c.references().createOrReuse(name, source, client,
                c.config().safeguards().referencesPerClient(), () -> {
            try (LoadProgress progress = LoadProgress.start(name, source)) {
                OntologyFiles.Loaded loaded = reader.apply(source);
                warnings.append(loaded.warnings());
                progress.parsed(loaded.ontology().getAxiomCount(),
                        loaded.ontology().getIndividualsInSignature().size(), reasoner);
                return Reference.open(name, loaded.ontology(), settings, c.config().reasonerTimeoutMs());
            }
        });
        if (mount) {
            takeMount(reference, client);
        }
        String statement = (source == null ? reference.createStatement() : reference.loadStatement()).text();
        if (!statement.isEmpty()) {
            warnings.append(warnings.isEmpty() ? "" : "; ").append(statement);
        }
        Optional<ArmorException> timedOut = reference.takeLoadTimeout();
        if (timedOut.isPresent()) {
            // Loaded, but not reasoned on: 211, and the reference is there (and journaled) for the next directive.
            return Response.failure(timedOut.get(), true).withDescription("reference '" + name + "' is loaded but"
                    + " its first reasoning was stopped: " + timedOut.get().getMessage()
                    + (warnings.isEmpty() ? "" : "; " + warnings));
        }
        return Response.ok(reference.isConsistent(), List.of()).withDescription(warnings.toString());
    }

    private static Response save(CommandContext c, boolean withInferences) {
        Reference reference = c.reference();
        String pathArgument = c.hasArg(0) ? c.arg(0) : reference.source();
        if (pathArgument == null || pathArgument.startsWith("http")) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "reference '" + reference.name()
                    + "' was not loaded from a file: SAVE needs a path");
        }
        OntologyFiles files = files(c);
        Path target = files.writablePath(pathArgument);
        String format = c.hasArg(1) ? c.arg(1) : "";
        if (withInferences) {
            files.save(Inferences.withInferences(reference), target, format.isEmpty() ? "rdfxml" : format);
        } else {
            files.save(reference.ontology(), target, format);
        }
        return c.ok();
    }

    private static Response mount(CommandContext c) {
        takeMount(c.reference(), c.directive().clientName());
        return c.ok();
    }

    private static void takeMount(Reference reference, String client) {
        String holder = reference.mountedBy();
        if (!holder.isEmpty() && !holder.equals(client)) {
            throw new ArmorException(ExitCode.MOUNT_REFUSED, "reference '" + reference.name()
                    + "' is mounted by client '" + holder + "'");
        }
        reference.setMountedBy(client);
    }

    private static Response unmount(CommandContext c) {
        String holder = c.reference().mountedBy();
        String client = c.directive().clientName();
        if (!holder.equals(client)) {
            throw new ArmorException(ExitCode.MOUNT_REFUSED, holder.isEmpty()
                    ? "reference '" + c.reference().name() + "' is not mounted"
                    : "reference '" + c.reference().name() + "' is mounted by client '" + holder + "', not '"
                    + client + "'");
        }
        c.reference().setMountedBy("");
        return c.ok();
    }
}
