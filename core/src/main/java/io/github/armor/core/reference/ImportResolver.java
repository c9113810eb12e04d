// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.io.IOException;
import java.net.URI;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.MissingImportEvent;
import org.semanticweb.owlapi.model.MissingImportListener;
import org.semanticweb.owlapi.model.OWLOntologyIRIMapper;

/**
 * Decides, for one LOAD, where every owl:imports is read from, and records why one is not.
 * In order: the {@code catalog-v001.xml} beside an importing document; a document in that
 * folder that declares the imported IRI (any syntax); the IRI itself when it names a local
 * file or a local jar; the web, only when web loading is on. Every local document must lie
 * inside allowed_dirs (symbolic links followed); nothing else is ever opened.
 *
 * <p>It is the manager's only IRI mapper, so the OWL API never falls back to fetching an import
 * IRI itself: a refused or unresolved import is sent to a document that fails at once, and the
 * missing-import event that follows is matched with the reason recorded here.
 */
final class ImportResolver implements OWLOntologyIRIMapper, MissingImportListener {
    // Opening it fails with ENOTDIR: no file is read, nothing is connected to.
    private static final IRI NOWHERE = IRI.create("file:/dev/null/armor-import-not-resolved");
    private static final Set<String> DOCUMENT_EXTENSIONS = Set.of("owl", "rdf", "xml", "owx", "ofn", "fss", "omn",
            "ttl", "nt", "n3");
    // A folder is indexed only when an import needs it; this bounds the work a huge folder costs.
    private static final int MAX_FOLDER_ENTRIES = 10_000;

    private final AllowedPaths allowed;
    private final boolean webLoading;
    // The importing documents' folders, the loaded document's first: imports of imports are
    // looked for beside the document that names them, and beside the earlier ones.
    private final List<Path> folders = new ArrayList<>();
    private final Map<Path, Optional<ImportCatalog>> catalogs = new HashMap<>();
    private final Map<Path, Map<String, Path>> declaredIn = new HashMap<>();
    private final Map<IRI, String> refused = new LinkedHashMap<>();
    private final Map<IRI, String> unresolved = new LinkedHashMap<>();

    ImportResolver(AllowedPaths allowed, boolean webLoading, Path documentFolder) {
        this.allowed = allowed;
        this.webLoading = webLoading;
        if (documentFolder != null) {
            folders.add(documentFolder);
        }
    }

    @Override
    public synchronized IRI getDocumentIRI(IRI imported) {
        try {
            return resolve(imported);
        } catch (Refusal refusal) {
            (refusal.outside ? refused : unresolved).putIfAbsent(imported, refusal.getMessage());
            return NOWHERE;
        }
    }

    @Override
    public synchronized void importMissing(MissingImportEvent event) {
        IRI imported = event.getImportedOntologyURI();
        if (!refused.containsKey(imported) && !unresolved.containsKey(imported)) {
            unresolved.put(imported, "could not be read: " + ParseComplaints.firstLine(event.getCreationException()));
        }
    }

    /**
     * After the load: 213 when an import leads outside allowed_dirs; 222 when imports stayed
     * unresolved, unless {@code lenient}, which answers their description for the LOAD's answer.
     */
    synchronized String verdict(String document, boolean lenient) {
        if (!refused.isEmpty()) {
            throw new ArmorException(ExitCode.PATH_NOT_ALLOWED, "LOAD of '" + document + "' refused: "
                    + describe(refused));
        }
        if (unresolved.isEmpty()) {
            return "";
        }
        String list = "imports not resolved: " + describe(unresolved);
        if (lenient) {
            return "loaded without its " + list;
        }
        throw new ArmorException(ExitCode.IMPORTS_UNRESOLVED, "LOAD of '" + document + "' refused, " + list
                + ". Put the documents beside it (or map them in its " + ImportCatalog.FILE_NAME + ")"
                + (webLoading ? "" : ", turn web_loading on") + ", or start the node with"
                + " ignore_missing_imports:=true to load it without them");
    }

    private static String describe(Map<IRI, String> reasons) {
        return reasons.entrySet().stream().map(e -> "<" + e.getKey() + "> " + e.getValue())
                .collect(Collectors.joining("; "));
    }

    private IRI resolve(IRI imported) throws Refusal {
        for (Path folder : List.copyOf(folders)) {
            Optional<ImportCatalog> catalog = catalog(folder);
            Optional<URI> listed = catalog.flatMap(c -> c.document(imported.toString()));
            if (listed.isPresent()) {
                return document(IRI.create(listed.get()), "(listed in " + catalog.get().file() + ") ");
            }
        }
        for (Path folder : List.copyOf(folders)) {
            Path declaring = declarations(folder).get(imported.toString());
            if (declaring != null) {
                return local(declaring);
            }
        }
        return document(imported, "");
    }

    /** A document named by an IRI: a local file or jar, confined, or a web address. */
    private IRI document(IRI iri, String via) throws Refusal {
        String scheme = iri.getScheme() == null ? "" : iri.getScheme().toLowerCase(Locale.ROOT);
        String text = iri.toString();
        if (scheme.equals("file")) {
            Path path = localPath(text);
            return local(confined(path, via + "names the file " + path));
        }
        if (scheme.equals("jar")) {
            int entry = text.indexOf("!/");
            String archive = entry < 0 ? "" : text.substring(4, entry);
            if (archive.startsWith("file:")) {
                confined(localPath(archive), via + "reads the archive " + archive);
                return iri;
            }
            if (archive.isEmpty()) {
                throw new Refusal(true, via + "names a resource of the core's own class path, not a file");
            }
            reachable(IRI.create(archive), via);
            // A remote archive: Java fetches it itself, following redirects on the same scheme only.
            return iri;
        }
        reachable(iri, via);
        try {
            return WebRedirects.finalLocation(iri);
        } catch (ArmorException e) {
            throw new Refusal(e.exitCode() == ExitCode.PATH_NOT_ALLOWED, e.getMessage());
        }
    }

    /** Refuses an address the web rule does not let the core fetch. */
    private void reachable(IRI address, String via) throws Refusal {
        String notFound = via + "was not found beside the importing document or in its " + ImportCatalog.FILE_NAME;
        if (!webLoading) {
            throw new Refusal(false, notFound + ", and web loading is off (node parameter web_loading)");
        }
        if (!WebRedirects.isWeb(address)) {
            throw new Refusal(false, notFound + ", and '" + address.getScheme() + ":' is not a web address (http, https)");
        }
    }

    private IRI local(Path file) {
        Path folder = file.getParent();
        if (folder != null && !folders.contains(folder)) {
            folders.add(folder);
        }
        return IRI.create(file.toFile());
    }

    private static Path localPath(String fileUri) throws Refusal {
        try {
            return Path.of(URI.create(fileUri));
        } catch (IllegalArgumentException e) {
            throw new Refusal(false, "is not a usable file address: " + e.getMessage());
        }
    }

    /** The final target of a local document, inside allowed_dirs and readable without blocking. */
    private Path confined(Path path, String what) throws Refusal {
        Path target;
        String refusal;
        try {
            target = AllowedPaths.finalTarget(path.toAbsolutePath());
            refusal = allowed.refusal(target);
        } catch (IOException | RuntimeException e) {
            throw new Refusal(true, what + ", which cannot be used: " + e);
        }
        if (refusal != null) {
            throw new Refusal(true, what + ", which " + refusal);
        }
        // A FIFO would block the load (and every LOAD after it) until someone writes to it.
        if (!Files.isRegularFile(target)) {
            throw new Refusal(false, what + ", which " + (Files.exists(target) ? "is not a regular file"
                    : "does not exist"));
        }
        return target;
    }

    private Optional<ImportCatalog> catalog(Path folder) {
        return catalogs.computeIfAbsent(folder, f -> {
            try {
                Optional<Path> file = allowed.inside(f.resolve(ImportCatalog.FILE_NAME));
                return file.isPresent() && Files.isRegularFile(file.get())
                        ? Optional.of(ImportCatalog.read(file.get())) : Optional.empty();
            } catch (IOException e) {
                return Optional.empty();
            }
        });
    }

    /** Declared ontology IRI -> document, for the documents of a folder that lie inside allowed_dirs. */
    private Map<String, Path> declarations(Path folder) {
        return declaredIn.computeIfAbsent(folder, f -> {
            Map<String, Path> declared = new HashMap<>();
            Map<String, Path> byName = new TreeMap<>();
            try (DirectoryStream<Path> entries = Files.newDirectoryStream(f)) {
                int seen = 0;
                for (Path entry : entries) {
                    if (++seen > MAX_FOLDER_ENTRIES) {
                        break;
                    }
                    String name = entry.getFileName().toString();
                    int dot = name.lastIndexOf('.');
                    if (!name.startsWith(".") && dot > 0
                            && DOCUMENT_EXTENSIONS.contains(name.substring(dot + 1).toLowerCase(Locale.ROOT))) {
                        byName.put(name, entry);
                    }
                }
            } catch (IOException e) {
                return declared;
            }
            for (Path entry : byName.values()) {
                try {
                    // Confined before it is opened: a link to a file outside is never read, and
                    // only a regular file (not a FIFO) can be read without blocking.
                    Optional<Path> inside = allowed.inside(entry);
                    if (inside.isPresent() && Files.isRegularFile(inside.get())) {
                        OntologyHeaders.declaredIri(inside.get()).ifPresent(iri -> declared.putIfAbsent(iri, inside.get()));
                    }
                } catch (IOException | RuntimeException e) {
                    // an unreadable document declares nothing
                }
            }
            return declared;
        });
    }

    /** Why an import is not read: outside allowed_dirs (213) or not found (222). */
    private static final class Refusal extends Exception {
        final boolean outside;

        Refusal(boolean outside, String reason) {
            super(reason, null, false, false);
            this.outside = outside;
        }
    }
}
