// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.durability;

import com.google.gson.JsonObject;
import io.github.armor.core.reference.Reference;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.zip.CRC32C;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.formats.FunctionalSyntaxDocumentFormat;
import org.semanticweb.owlapi.functional.renderer.FunctionalSyntaxObjectRenderer;
import org.semanticweb.owlapi.io.StreamDocumentSource;
import org.semanticweb.owlapi.model.AddImport;
import org.semanticweb.owlapi.model.AddOntologyAnnotation;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.MissingImportHandlingStrategy;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLDocumentFormat;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyLoaderConfiguration;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLOntologyStorageException;

/**
 * A reference's ontology as a file of the state directory, in OWL functional syntax, kept only
 * once it has been read back and found equal: an ontology it cannot carry (an IRI holding
 * {@code <} or {@code >}, which RDF/XML accepts; neither OWL/XML nor RDF/XML reads such an IRI
 * back either) is refused at LOAD rather than lost at the next restart. Its CRC32C and length go
 * into meta, so a restore tells a damaged checkpoint from a good one.
 */
final class CheckpointFile {
    private static final int BUFFER_BYTES = 1 << 16;

    /** One written checkpoint, as meta names it. */
    record Written(String file, long crc32c, long bytes, long revision) {
        JsonObject toJson() {
            JsonObject json = new JsonObject();
            json.addProperty("file", file);
            json.addProperty("crc32c", crc32c);
            json.addProperty("bytes", bytes);
            json.addProperty("revision", revision);
            return json;
        }

        static Written fromJson(JsonObject json) {
            return new Written(json.get("file").getAsString(), json.get("crc32c").getAsLong(),
                    json.get("bytes").getAsLong(), json.get("revision").getAsLong());
        }
    }

    private CheckpointFile() {
    }

    /** A written checkpoint that does not parse. */
    private static final class Unreadable extends RuntimeException {
        Unreadable(String why) {
            super(why);
        }
    }

    /** The ontology's own axioms, annotations and imports, with its prefixes, in a manager of its own. */
    static OWLOntology snapshot(Reference reference) {
        OWLOntology live = reference.ontology();
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        try {
            OWLOntology copy = manager.createOntology(live.getOntologyID());
            manager.addAxioms(copy, live.axioms());
            live.annotations().forEach(a -> manager.applyChange(new AddOntologyAnnotation(copy, a)));
            live.importsDeclarations().forEach(i -> manager.applyChange(new AddImport(copy, i)));
            OWLDocumentFormat original = reference.manager().getOntologyFormat(live);
            FunctionalSyntaxDocumentFormat format = new FunctionalSyntaxDocumentFormat();
            if (original != null && original.isPrefixOWLDocumentFormat()) {
                format.copyPrefixesFrom(original.asPrefixOWLDocumentFormat());
            }
            manager.setOntologyFormat(copy, format);
            return copy;
        } catch (OWLOntologyCreationException e) {
            throw new IllegalStateException("could not copy ontology of '" + reference.name() + "'", e);
        }
    }

    /**
     * Writes {@code copy} as {@code checkpoint-<seq>} in {@code dir} (a temporary file forced to
     * disk, read back and compared, then renamed in place and the directory forced). Nothing of
     * it is left behind when it fails.
     */
    static Written write(Storage storage, OWLOntology copy, Path dir, long seq, long revision) throws IOException {
        String name = "checkpoint-" + seq + ".ofn";
        Path temporary = dir.resolve(name + ".tmp");
        try {
            long[] crcAndBytes = save(storage, copy, temporary);
            String difference;
            try {
                difference = difference(copy, readBack(storage.read(temporary), copy));
            } catch (Unreadable e) {
                difference = "it does not parse (" + e.getMessage() + ")";
            }
            if (difference != null) {
                throw new IOException("the ontology cannot be kept: its checkpoint does not read back the same: "
                        + difference + unwritableIri(copy));
            }
            storage.rename(temporary, dir.resolve(name));
            storage.syncDirectory(dir);
            return new Written(name, crcAndBytes[0], crcAndBytes[1], revision);
        } catch (IOException | RuntimeException e) {
            deleteQuietly(storage, temporary);
            throw e instanceof IOException io ? io : new IOException("cannot write " + name + ": " + e, e);
        }
    }

    /** Names an IRI OWL functional syntax cannot write (it writes IRIs between < and >), if any. */
    private static String unwritableIri(OWLOntology ontology) {
        return ontology.signature().map(e -> e.getIRI().toString())
                .filter(iri -> iri.chars().anyMatch(c -> c == '<' || c == '>' || Character.isWhitespace(c)))
                .findFirst().map(iri -> "; the IRI '" + iri + "' holds a character functional syntax cannot write")
                .orElse("");
    }

    /** Checks a checkpoint's bytes against meta before it is parsed. */
    static void check(Storage storage, Path dir, Written checkpoint) throws IOException {
        if (checkpoint.bytes() < 0) {
            return; // written by a version without checksums
        }
        byte[] bytes = storage.read(dir.resolve(checkpoint.file()));
        CRC32C crc = new CRC32C();
        crc.update(bytes);
        if (bytes.length != checkpoint.bytes() || crc.getValue() != checkpoint.crc32c()) {
            throw new IOException(checkpoint.file() + " is damaged: " + bytes.length + " bytes with CRC32C "
                    + Long.toHexString(crc.getValue()) + ", meta says " + checkpoint.bytes() + " bytes with "
                    + Long.toHexString(checkpoint.crc32c()));
        }
    }

    private static long[] save(Storage storage, OWLOntology copy, Path file) throws IOException {
        OWLDocumentFormat format = copy.getOWLOntologyManager().getOntologyFormat(copy);
        CRC32C crc = new CRC32C();
        try (Storage.Output out = storage.create(file)) {
            OutputStream stream = new OutputStream() {
                private final ByteBuffer buffer = ByteBuffer.allocate(BUFFER_BYTES);

                @Override
                public void write(int b) throws IOException {
                    write(new byte[] {(byte) b}, 0, 1);
                }

                @Override
                public void write(byte[] bytes, int offset, int length) throws IOException {
                    crc.update(bytes, offset, length);
                    while (length > 0) {
                        int n = Math.min(length, buffer.remaining());
                        buffer.put(bytes, offset, n);
                        offset += n;
                        length -= n;
                        if (!buffer.hasRemaining()) {
                            flush();
                        }
                    }
                }

                @Override
                public void flush() throws IOException {
                    buffer.flip();
                    out.write(buffer);
                    buffer.clear();
                }
            };
            try {
                copy.getOWLOntologyManager().saveOntology(copy, format, stream);
            } catch (OWLOntologyStorageException e) {
                throw new IOException("cannot write checkpoint: " + e.getMessage(), e);
            }
            stream.flush();
            out.force();
            return new long[] {crc.getValue(), out.size()};
        }
    }

    /** Parses what was written, without following its imports (they are not part of it). */
    private static OWLOntology readBack(byte[] bytes, OWLOntology copy) {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        OWLOntologyLoaderConfiguration configuration = new OWLOntologyLoaderConfiguration()
                .setMissingImportHandlingStrategy(MissingImportHandlingStrategy.SILENT)
                .setReportStackTraces(false);
        for (var declaration : copy.importsDeclarations().toList()) {
            configuration = configuration.addIgnoredImport(declaration.getIRI());
        }
        try {
            return manager.loadOntologyFromOntologyDocument(new StreamDocumentSource(new ByteArrayInputStream(bytes),
                    "urn:armor:checkpoint", new FunctionalSyntaxDocumentFormat(), null), configuration);
        } catch (OWLOntologyCreationException | RuntimeException e) {
            String message = String.valueOf(e.getMessage());
            throw new Unreadable(message.substring(0, Math.min(3000, message.length())));
        }
    }

    /**
     * Why {@code read} is not {@code written} (null when it is): the same ID, imports, annotations
     * and axioms (declarations the writer added aside). Axioms about anonymous individuals are
     * counted, as their labels may change.
     */
    static String difference(OWLOntology written, OWLOntology read) {
        // An anonymous ontology reads back anonymous, under another label.
        if (!(written.getOntologyID().isAnonymous() && read.getOntologyID().isAnonymous())
                && !written.getOntologyID().equals(read.getOntologyID())) {
            return "its ontology IRI reads back as " + read.getOntologyID();
        }
        if (!written.importsDeclarations().toList().equals(read.importsDeclarations().toList())
                || !new HashSet<>(written.annotations().toList()).equals(new HashSet<>(read.annotations().toList()))) {
            return "its imports or ontology annotations differ";
        }
        Set<OWLAxiom> named = new HashSet<>();
        long anonymous = 0;
        for (OWLAxiom axiom : written.axioms().toList()) {
            if (axiom.anonymousIndividuals().findAny().isPresent()) {
                anonymous++;
            } else {
                named.add(axiom);
            }
        }
        long readAnonymous = 0;
        List<OWLAxiom> unwritten = new ArrayList<>();
        for (OWLAxiom axiom : read.axioms().toList()) {
            if (axiom.anonymousIndividuals().findAny().isPresent()) {
                readAnonymous++;
            } else if (!named.remove(axiom) && !axiom.isOfType(AxiomType.DECLARATION)) {
                // The writers declare every entity they write; a declaration more is no change.
                unwritten.add(axiom);
            }
        }
        // What functional syntax cannot say reads back as what it says: an intersection or union
        // of one class (owl:intersectionOf a one-member list, as LUBM's univ-bench has) is
        // written as that class. Such pairs are the same text in that syntax, and the same class.
        Map<String, Integer> leftover = new HashMap<>();
        named.forEach(axiom -> leftover.merge(functional(written, axiom), 1, Integer::sum));
        for (OWLAxiom axiom : unwritten) {
            String text = functional(written, axiom);
            if (leftover.getOrDefault(text, 0) == 0) {
                return "it holds an axiom that was not written: " + axiom;
            }
            leftover.merge(text, -1, Integer::sum);
        }
        leftover.values().removeIf(count -> count == 0);
        if (!leftover.isEmpty()) {
            return leftover.size() + " axiom(s) are missing, such as " + leftover.keySet().iterator().next();
        }
        return anonymous == readAnonymous ? null
                : anonymous + " axioms about anonymous individuals read back as " + readAnonymous;
    }

    /** An axiom as OWL functional syntax writes it. */
    private static String functional(OWLOntology ontology, OWLAxiom axiom) {
        java.io.StringWriter text = new java.io.StringWriter();
        axiom.accept(new FunctionalSyntaxObjectRenderer(ontology, text));
        return text.toString();
    }

    private static void deleteQuietly(Storage storage, Path file) {
        try {
            storage.deleteIfExists(file);
        } catch (IOException e) {
            // Left for the next restore's clean-up: it deletes files meta does not name.
        }
    }
}
