// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.formats.FunctionalSyntaxDocumentFormat;
import org.semanticweb.owlapi.formats.ManchesterSyntaxDocumentFormat;
import org.semanticweb.owlapi.formats.OWLXMLDocumentFormat;
import org.semanticweb.owlapi.formats.RDFXMLDocumentFormat;
import org.semanticweb.owlapi.formats.TurtleDocumentFormat;
import org.semanticweb.owlapi.io.FileDocumentSource;
import org.semanticweb.owlapi.io.IRIDocumentSource;
import org.semanticweb.owlapi.io.OWLOntologyDocumentSource;
import org.semanticweb.owlapi.io.UnparsableOntologyException;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.MissingImportHandlingStrategy;
import org.semanticweb.owlapi.model.OWLDocumentFormat;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLOntologyStorageException;
import org.semanticweb.owlapi.util.AutoIRIMapper;

/**
 * Reading and writing ontology documents, with the security rules: client paths stay inside the
 * configured directories, and nothing is fetched from the web unless web loading is on (also
 * owl:imports, which are resolved from the document's own directory instead).
 */
public final class OntologyFiles {
    private static final Map<String, Supplier<OWLDocumentFormat>> FORMATS = Map.of(
            "RDFXML", RDFXMLDocumentFormat::new,
            "OWLXML", OWLXMLDocumentFormat::new,
            "TURTLE", TurtleDocumentFormat::new,
            "FUNCTIONAL", FunctionalSyntaxDocumentFormat::new,
            "MANCHESTER", ManchesterSyntaxDocumentFormat::new);

    // These parsers accept almost any text as an (empty) ontology, which would turn a corrupt
    // file into a silent success; robotics ontologies never use their formats.
    private static final List<String> LENIENT_PARSERS = List.of("OBO", "KRSS", "DL Syntax", "LaTeX");

    private final CoreConfig config;

    public OntologyFiles(CoreConfig config) {
        this.config = config;
    }

    /** A fresh manager configured so that loading never reaches the network on its own. */
    public OWLOntologyManager newManager(Path documentDirectory) {
        OWLOntologyManager manager = OWLManager.createOWLOntologyManager();
        manager.setOntologyParsers(java.util.stream.StreamSupport.stream(manager.getOntologyParsers().spliterator(), false)
                .filter(p -> LENIENT_PARSERS.stream().noneMatch(p.getSupportedFormat().getKey()::contains))
                .collect(java.util.stream.Collectors.toSet()));
        manager.setOntologyLoaderConfiguration(manager.getOntologyLoaderConfiguration()
                .setMissingImportHandlingStrategy(MissingImportHandlingStrategy.SILENT)
                .setFollowRedirects(config.webLoading()));
        if (!config.webLoading()) {
            // Consulted last: any import the directory does not provide is sent nowhere.
            manager.getIRIMappers().add(iri -> iri.getScheme() != null && iri.getScheme().startsWith("http")
                    ? IRI.create("file:/nonexistent/armor-web-loading-disabled") : null);
        }
        if (documentDirectory != null) {
            manager.getIRIMappers().add(new AutoIRIMapper(documentDirectory.toFile(), false));
        }
        return manager;
    }

    /** A client path, made absolute and checked against the allowed directories. */
    public Path allowedPath(String clientPath) {
        if (clientPath == null || clientPath.isBlank()) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "empty path");
        }
        Path path;
        try {
            path = Path.of(clientPath.trim()).toAbsolutePath().normalize();
            Path existing = path;
            while (existing != null && !Files.exists(existing)) {
                existing = existing.getParent();
            }
            Path real = existing == null ? path : existing.toRealPath().resolve(existing.relativize(path));
            for (Path allowed : config.allowedDirs()) {
                Path root = Files.exists(allowed) ? allowed.toRealPath() : allowed.toAbsolutePath().normalize();
                if (real.startsWith(root)) {
                    return real;
                }
            }
        } catch (IOException | RuntimeException e) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath + "' cannot be used: " + e);
        }
        throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "path '" + clientPath
                + "' is outside the allowed directories " + config.allowedDirs()
                + " (node parameter allowed_dirs)");
    }

    public OWLOntology loadFile(String clientPath) {
        Path path = allowedPath(clientPath);
        if (!Files.isRegularFile(path)) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "no such file: '" + clientPath + "'");
        }
        return load(newManager(path.getParent()), new FileDocumentSource(path.toFile()), clientPath);
    }

    /** A file the core wrote itself (a checkpoint): no path confinement, imports resolved from importsDir. */
    public OWLOntology loadTrusted(Path file, Path importsDir) {
        OWLOntologyManager manager = newManager(importsDir);
        return load(manager, new FileDocumentSource(file.toFile()), file.toString());
    }

    public OWLOntology loadWeb(String url) {
        if (!config.webLoading()) {
            throw new ArmorException(ExitCode.WEB_LOADING_DISABLED,
                    "LOAD WEB is disabled; start the node with web_loading:=true to allow it");
        }
        IRI iri = IRI.create(url.trim());
        if (iri.getScheme() == null || !iri.getScheme().startsWith("http")) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "'" + url + "' is not an http(s) URL");
        }
        return load(newManager(null), new IRIDocumentSource(iri), url);
    }

    public OWLOntology create(String ontologyIri) {
        try {
            OWLOntologyManager manager = newManager(null);
            return ontologyIri.isBlank() ? manager.createOntology() : manager.createOntology(IRI.create(ontologyIri));
        } catch (OWLOntologyCreationException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not create ontology '" + ontologyIri + "': "
                    + e.getMessage(), e);
        }
    }

    /** Writes atomically (temporary file, then rename) so a crash never leaves half a document. */
    public void save(OWLOntology ontology, Path target, String formatName) {
        OWLDocumentFormat format = format(ontology, formatName);
        try {
            Files.createDirectories(target.toAbsolutePath().getParent());
            Path temporary = Files.createTempFile(target.toAbsolutePath().getParent(), ".armor-save", ".tmp");
            // A temporary file is private (0600); the saved ontology is an ordinary document.
            Files.setPosixFilePermissions(temporary, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
            try (OutputStream out = Files.newOutputStream(temporary)) {
                ontology.getOWLOntologyManager().saveOntology(ontology, format, out);
            }
            Files.move(temporary, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException | OWLOntologyStorageException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not save to '" + target + "': " + e.getMessage(), e);
        }
    }

    private OWLDocumentFormat format(OWLOntology ontology, String formatName) {
        if (formatName == null || formatName.isBlank()) {
            OWLDocumentFormat loaded = ontology.getOWLOntologyManager().getOntologyFormat(ontology);
            return loaded != null ? loaded : new RDFXMLDocumentFormat();
        }
        Supplier<OWLDocumentFormat> chosen = FORMATS.get(formatName.trim().toUpperCase(Locale.ROOT)
                .replace("/", "").replace("_", "").replace("-", ""));
        if (chosen == null) {
            throw new ArmorException(ExitCode.WRONG_ARGUMENTS, "unknown format '" + formatName
                    + "': expected rdfxml, owlxml, turtle, functional or manchester");
        }
        OWLDocumentFormat format = chosen.get();
        OWLDocumentFormat loaded = ontology.getOWLOntologyManager().getOntologyFormat(ontology);
        if (loaded != null && loaded.isPrefixOWLDocumentFormat() && format.isPrefixOWLDocumentFormat()) {
            format.asPrefixOWLDocumentFormat().copyPrefixesFrom(loaded.asPrefixOWLDocumentFormat());
        }
        return format;
    }

    private static OWLOntology load(OWLOntologyManager manager, OWLOntologyDocumentSource source, String name) {
        try {
            return manager.loadOntologyFromOntologyDocument(source);
        } catch (UnparsableOntologyException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not parse '" + name + "': " + parserComplaint(e), e);
        } catch (OWLOntologyCreationException | RuntimeException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not load '" + name + "': " + firstLines(e), e);
        }
    }

    /** The complaint of the parser that got furthest into the document, not the OWL API's preamble. */
    private static String parserComplaint(UnparsableOntologyException e) {
        String best = null;
        long furthest = -1;
        for (var entry : e.getExceptions().entrySet()) {
            String message = String.valueOf(entry.getValue().getMessage()).strip();
            java.util.regex.Matcher line = java.util.regex.Pattern.compile("(?i)line[^0-9]{0,3}(\\d+)").matcher(message);
            long reached = line.find() ? Long.parseLong(line.group(1)) : 0;
            if (reached > furthest) {
                furthest = reached;
                best = entry.getKey().getClass().getSimpleName() + ": " + message;
            }
        }
        String complaint = best == null ? firstLines(e) : best.replaceAll("\\s+", " ");
        return complaint.length() > 600 ? complaint.substring(0, 600) + " ..." : complaint;
    }

    private static String firstLines(Exception e) {
        String message = String.valueOf(e.getMessage()).strip();
        return message.length() > 600 ? message.substring(0, 600) + " ..." : message;
    }
}
