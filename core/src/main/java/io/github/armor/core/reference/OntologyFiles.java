// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
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
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Reading and writing ontology documents, with the security rules: what a client names is read
 * only inside allowed_dirs ({@link AllowedPaths}) and written only inside write_dirs
 * ({@link WritablePaths}), owl:imports resolve only to documents inside allowed_dirs too (or the
 * web, when web loading is on), and no parser fetches an external entity.
 */
public final class OntologyFiles {
    private static final Logger LOG = LoggerFactory.getLogger(OntologyFiles.class);
    private static final Map<String, Supplier<OWLDocumentFormat>> FORMATS = Map.of(
            "RDFXML", RDFXMLDocumentFormat::new,
            "OWLXML", OWLXMLDocumentFormat::new,
            "TURTLE", TurtleDocumentFormat::new,
            "FUNCTIONAL", FunctionalSyntaxDocumentFormat::new,
            "MANCHESTER", ManchesterSyntaxDocumentFormat::new);

    // These parsers accept almost any text as an (empty) ontology, which would turn a corrupt
    // file into a silent success; robotics ontologies never use their formats. HDT, BinaryRDF
    // and RDFa are binary or HTML formats: their complaints about a text file only confuse.
    private static final List<String> UNUSED_PARSERS = List.of("OBO", "KRSS", "DL Syntax", "LaTeX", "HDT",
            "BinaryRDF", "RDFa");

    /** A loaded document, and what the LOAD's answer must say about it (unresolved imports). */
    public record Loaded(OWLOntology ontology, String warnings) {}

    private final CoreConfig config;
    private final AllowedPaths allowed;
    private final WritablePaths writable;

    public OntologyFiles(CoreConfig config) {
        this.config = config;
        this.allowed = AllowedPaths.forReading(config);
        this.writable = WritablePaths.of(config);
    }

    /**
     * A fresh manager whose imports go through {@code imports} only, so that loading never
     * reaches a file or the network on its own.
     */
    private static OWLOntologyManager newManager(ImportResolver imports) {
        // Concurrent: the web view reads a reference's ontology without its lock while a writer changes it.
        OWLOntologyManager manager = OWLManager.createConcurrentOWLOntologyManager();
        manager.setOntologyParsers(java.util.stream.StreamSupport.stream(manager.getOntologyParsers().spliterator(), false)
                .filter(p -> UNUSED_PARSERS.stream().noneMatch(p.getSupportedFormat().getKey()::contains))
                .collect(java.util.stream.Collectors.toSet()));
        manager.setOntologyLoaderConfiguration(manager.getOntologyLoaderConfiguration()
                .setMissingImportHandlingStrategy(MissingImportHandlingStrategy.SILENT)
                // WebRedirects follows them, refusing any that leaves http(s).
                .setFollowRedirects(false));
        manager.getIRIMappers().clear();
        manager.getIRIMappers().add(imports);
        manager.addMissingImportListener(imports);
        return manager;
    }

    /** A manager that resolves no import at all: for CREATE and for ontology text a client sends (ADD AXIOM). */
    public static OWLOntologyManager inlineManager() {
        return newManager(new ImportResolver(new AllowedPaths(List.of()), false, null));
    }

    /** A client path to read, made absolute and checked against allowed_dirs (symbolic links followed). */
    public Path allowedPath(String clientPath) {
        return allowed.check(clientPath);
    }

    /** A client path to write, made absolute and checked against write_dirs (symbolic links followed). */
    public Path writablePath(String clientPath) {
        return writable.check(clientPath);
    }

    public Loaded loadFile(String clientPath) {
        Path path = allowedPath(clientPath);
        if (!Files.isRegularFile(path)) {
            throw new ArmorException(ExitCode.LOAD_FAILED, Files.exists(path)
                    ? "'" + path + "' is not a regular file" : "no such file: " + path);
        }
        ImportResolver imports = new ImportResolver(allowed, config.webLoading(), path.getParent());
        OWLOntology ontology = load(newManager(imports), LoadProgress.counted(path.toFile()), clientPath,
                () -> OntologyHeaders.likelySyntax(path));
        return new Loaded(ontology, imports.verdict(clientPath, config.safeguards().ignoreMissingImports()));
    }

    /**
     * A file the core wrote itself (a checkpoint): no path confinement for it, and its imports
     * resolved beside importsDir under the usual rules; one that no longer resolves is left out
     * with a warning rather than losing the reference.
     */
    public OWLOntology loadTrusted(Path file, Path importsDir) {
        ImportResolver imports = new ImportResolver(allowed, config.webLoading(), importsDir);
        OWLOntology ontology = load(newManager(imports), new FileDocumentSource(file.toFile()), file.toString(),
                () -> OntologyHeaders.likelySyntax(file));
        try {
            String warnings = imports.verdict(file.toString(), true);
            if (!warnings.isEmpty()) {
                LOG.warn("{}: {}", file, warnings);
            }
        } catch (ArmorException e) {
            LOG.warn("{}: {}", file, e.getMessage());
        }
        return ontology;
    }

    public Loaded loadWeb(String url) {
        if (!config.webLoading()) {
            throw new ArmorException(ExitCode.WEB_LOADING_DISABLED,
                    "LOAD WEB is disabled; start the node with web_loading:=true to allow it");
        }
        IRI iri = IRI.create(url.trim());
        if (!WebRedirects.isWeb(iri)) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "'" + url + "' is not an http(s) URL");
        }
        ImportResolver imports = new ImportResolver(allowed, true, null);
        OWLOntology ontology = load(newManager(imports), new IRIDocumentSource(WebRedirects.finalLocation(iri)), url,
                Optional::empty);
        return new Loaded(ontology, imports.verdict(url, config.safeguards().ignoreMissingImports()));
    }

    public OWLOntology create(String ontologyIri) {
        // Checked first: an IRI the checkpoint's syntax cannot write back would be refused as not durable.
        IRI iri = ontologyIri.isBlank() ? null : EntityResolver.absoluteIri(ontologyIri, ontologyIri);
        try {
            OWLOntologyManager manager = inlineManager();
            return iri == null ? manager.createOntology() : manager.createOntology(iri);
        } catch (OWLOntologyCreationException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not create ontology '" + ontologyIri + "': "
                    + e.getMessage(), e);
        }
    }

    /**
     * Writes to a target {@link #writablePath} checked, atomically (temporary file, then rename)
     * so a crash never leaves half a document.
     */
    public void save(OWLOntology ontology, Path target, String formatName) {
        OWLDocumentFormat format = format(ontology, formatName);
        writable.write(target, out -> {
            try {
                ontology.getOWLOntologyManager().saveOntology(ontology, format, out);
            } catch (OWLOntologyStorageException e) {
                throw new IOException(e.getMessage(), e);
            }
        });
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

    private static OWLOntology load(OWLOntologyManager manager, OWLOntologyDocumentSource source, String name,
                                    Supplier<Optional<OntologyHeaders.Syntax>> looksLike) {
        try {
            return manager.loadOntologyFromOntologyDocument(source);
        } catch (UnparsableOntologyException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, ParseComplaints.explain(name, e, looksLike.get()), e);
        } catch (OWLOntologyCreationException | RuntimeException e) {
            throw new ArmorException(ExitCode.LOAD_FAILED, "could not load '" + name + "': "
                    + ParseComplaints.firstLine(e), e);
        }
    }
}
