// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core;

import static io.github.armor.core.CoreFixture.assertFails;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.net.httpserver.HttpServer;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Response;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * owl:imports (issue 21 items 2-3, issue 20 item 1): resolved beside the importing document in
 * every syntax and through catalog-v001.xml, always inside allowed_dirs; an import that cannot
 * be resolved is named in a 222 (or, under ignore_missing_imports, in the LOAD's description).
 */
class ImportsTest {
    private static final Path IMPORTS = CoreFixture.TEST_ONTOLOGIES.resolve("imports");
    private static final String SECRET = "http://www.example.org/armor-test/secret";

    @TempDir
    Path scratch;
    @TempDir
    Path outside;

    private static CoreConfig config(List<Path> allowed, boolean webLoading, boolean lenient) {
        return new CoreConfig(true, "HERMIT", allowed, webLoading, 30_000, 0, 0, CoreConfig.Durability.NONE,
                new CoreConfig.Safeguards(30_000, false, lenient));
    }

    private CoreFixture fixture(boolean webLoading, boolean lenient) {
        return new CoreFixture(config(List.of(CoreFixture.TEST_ONTOLOGIES, scratch), webLoading, lenient));
    }

    private static Response load(CoreFixture f, String reference, Path file) {
        return f.run(reference, "LOAD FILE", file.toString(), "", "false", "HERMIT", "false");
    }

    private static Path importer(Path folder, String... imports) throws IOException {
        StringBuilder text = new StringBuilder("Ontology(<http://www.example.org/armor-test/importer>\n");
        for (String imported : imports) {
            text.append("Import(<").append(imported).append(">)\n");
        }
        text.append("Declaration(Class(<http://www.example.org/armor-test/importer#A>))\n)\n");
        Files.createDirectories(folder);
        return Files.writeString(folder.resolve("importer-" + System.nanoTime() + ".owl"), text);
    }

    private Path secret() throws IOException {
        return Files.writeString(outside.resolve("secret.owl"), "Ontology(<" + SECRET + ">\n"
                + "Declaration(Class(<" + SECRET + "#TopSecret>))\n)\n");
    }

    @Test
    void aFunctionalSyntaxImportResolvesFromTheSameFolder() {
        CoreFixture f = fixture(false, false);
        Response loaded = load(f, "tasks", IMPORTS.resolve("functional/tasks.owl"));
        assertTrue(loaded.success(), loaded.errorDescription());
        // No word about imports: only what every LOAD says (profile, classes, how it is reasoned on).
        // An ontology with imports is classified in the background: done or not yet, by load.
        assertTrue(loaded.errorDescription().matches("profile: OWL 2 DL; \\d+ classes, (being )?classified in [^;]+;"
                + " reasoning in modules: .*"), loaded.errorDescription());
        assertEquals(List.of("<http://www.example.org/armor-test/tasks#goToKitchen>"),
                f.ok("tasks", "QUERY IND CLASS", "<http://www.example.org/armor-test/upper#Event>").queriedObjects());
    }

    @Test
    void anRdfXmlImportDeclaredWithRdfAboutResolvesFromTheSameFolder() {
        CoreFixture f = fixture(false, false);
        f.ok("site", "LOAD FILE", IMPORTS.resolve("rdfxml/site.owl").toString(), "", "false", "HERMIT", "false");
        assertEquals(List.of("<http://www.example.org/armor-test/site#lab>"),
                f.ok("site", "QUERY IND CLASS", "<http://www.example.org/armor-test/map#Location>").queriedObjects());
    }

    @Test
    void aCatalogMapsAnImportToADocumentInASubfolder() {
        CoreFixture f = fixture(false, false);
        f.ok("tasks", "LOAD FILE", IMPORTS.resolve("catalog/robot-tasks.ttl").toString(), "", "false", "HERMIT",
                "false");
        assertEquals(List.of("<http://www.example.org/armor-test/robot-tasks#gripper1>"),
                f.ok("tasks", "QUERY IND CLASS", "<http://www.example.org/armor-test/vendor#Gripper>")
                        .queriedObjects());
    }

    @Test
    void importsOfImportsResolveBesideTheDocumentThatNamesThem() throws IOException {
        Path nested = scratch.resolve("nested");
        Files.createDirectories(nested);
        Files.writeString(nested.resolve("middle.owl"), "Ontology(<http://www.example.org/armor-test/middle>\n"
                + "Import(<http://www.example.org/armor-test/leaf>)\n)\n");
        Files.writeString(nested.resolve("leaf.owl"), "Ontology(<http://www.example.org/armor-test/leaf>\n"
                + "Declaration(Class(<http://www.example.org/armor-test/leaf#Leaf>))\n)\n");
        Path top = importer(scratch.resolve("top"), nested.resolve("middle.owl").toUri().toString());
        CoreFixture f = fixture(false, false);
        Response loaded = load(f, "top", top);
        assertTrue(loaded.success(), loaded.errorDescription());
        assertTrue(f.ok("top", "QUERY SPARQL", "ASK { <http://www.example.org/armor-test/leaf#Leaf> ?p ?o }")
                .queriedObjects().contains("true"));
    }

    @Test
    void aRestoredReferenceResolvesItsImportsBesideItsSourceAgain() {
        Path state = scratch.resolve("state");
        CoreConfig.Durability durability = new CoreConfig.Durability(state, true, false, 1, 3600);
        CoreConfig config = new CoreConfig(true, "HERMIT", List.of(CoreFixture.TEST_ONTOLOGIES, scratch), false,
                30_000, 0, 0, durability, CoreConfig.Safeguards.DEFAULT);
        String event = "<http://www.example.org/armor-test/upper#Event>";
        try (ArmorCore first = new ArmorCore(config)) {
            first.restoreState();
            CoreFixture f = new CoreFixture(first);
            f.ok("tasks", "LOAD FILE", IMPORTS.resolve("functional/tasks.owl").toString(), "", "false", "HERMIT",
                    "false");
            // One change: the reference is checkpointed, then restored from that checkpoint.
            f.ok("tasks", "ADD IND CLASS", "patrol", "Navigation");
        }
        try (ArmorCore second = new ArmorCore(config)) {
            second.restoreState();
            assertEquals(List.of("<http://www.example.org/armor-test/tasks#goToKitchen>",
                    "<http://www.example.org/armor-test/tasks#patrol>"),
                    new CoreFixture(second).ok("tasks", "QUERY IND CLASS", event).queriedObjects());
        }
    }

    @Test
    void anUnresolvedImportIs222NamingItAndWhy() {
        CoreFixture f = fixture(false, false);
        Response refused = load(f, "students", IMPORTS.resolve("web-only/students.owl"));
        assertFails(refused, 222);
        assertTrue(refused.errorDescription().contains("<http://www.example.org/armor-test/university.owl>"));
        assertTrue(refused.errorDescription().contains("web_loading"));
        assertTrue(refused.errorDescription().contains("ignore_missing_imports"));
        assertFails(f.run("students", "QUERY IND CLASS", "Student"), 206);
    }

    @Test
    void theLenientRuleLoadsAndListsTheUnresolvedImports() {
        CoreFixture f = fixture(false, true);
        Response loaded = load(f, "students", IMPORTS.resolve("web-only/students.owl"));
        assertTrue(loaded.success() && loaded.exitCode() == 0, loaded.errorDescription());
        assertTrue(loaded.errorDescription().contains("<http://www.example.org/armor-test/university.owl>"),
                loaded.errorDescription());
    }

    @Test
    void importsLeadingOutsideAllowedDirsAre213EvenUnderTheLenientRule() throws IOException {
        Path secret = secret();
        Path jar = outside.resolve("secret.jar");
        try (ZipOutputStream zip = new ZipOutputStream(Files.newOutputStream(jar))) {
            zip.putNextEntry(new ZipEntry("secret.owl"));
            zip.write(Files.readAllBytes(secret));
        }
        Path link = scratch.resolve("innocent.owl");
        Files.createSymbolicLink(link, secret);
        for (boolean lenient : List.of(false, true)) {
            CoreFixture f = fixture(false, lenient);
            for (String imported : List.of(secret.toUri().toString(), "jar:" + jar.toUri() + "!/secret.owl",
                    link.toUri().toString(), "jar:!/io/github/armor/core/ArmorCore.class")) {
                Response refused = load(f, "attack", importer(scratch, imported));
                assertFails(refused, 213);
                assertTrue(refused.errorDescription().contains(imported), refused.errorDescription());
            }
            assertFails(f.run("attack", "QUERY IND CLASS", "TopSecret"), 206);
        }
    }

    @Test
    void aCatalogEntryLeadingOutsideAllowedDirsIs213() throws IOException {
        secret();
        Path folder = scratch.resolve("catalogued");
        Path importing = importer(folder, SECRET);
        Files.writeString(folder.resolve("catalog-v001.xml"), "<catalog xmlns=\"urn:oasis:names:tc:entity:xmlns:xml:catalog\">"
                + "<uri name=\"" + SECRET + "\" uri=\"" + folder.relativize(outside.resolve("secret.owl")) + "\"/></catalog>");
        assertFails(load(fixture(false, false), "attack", importing), 213);
    }

    @Test
    void aDocumentLinkedFromOutsideIsNeverReadByTheFolderScan() throws IOException {
        Files.createSymbolicLink(scratch.resolve("secret.owl"), secret());
        Response refused = load(fixture(false, false), "attack", importer(scratch, SECRET));
        assertFails(refused, 222);
    }

    @Test
    void aFifoBesideTheImportingFileBlocksNothing() throws Exception {
        Path fifo = scratch.resolve("upper.owl");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).start();
        assertEquals(0, mkfifo.waitFor());
        Response refused = load(fixture(false, false), "attack", importer(scratch, "http://www.example.org/x/upper",
                fifo.toUri().toString()));
        assertFails(refused, 222);
        assertTrue(refused.errorDescription().contains("not a regular file"), refused.errorDescription());
    }

    @Test
    void anImportInsideAnAxiomIsRefusedAndNeverFetched() throws Exception {
        CoreFixture f = fixture(false, false);
        f.ok("tasks", "LOAD FILE", IMPORTS.resolve("functional/tasks.owl").toString(), "", "false", "HERMIT", "false");
        try (java.net.ServerSocket listener = new java.net.ServerSocket(0, 50, java.net.InetAddress.getLoopbackAddress())) {
            listener.setSoTimeout(1);
            Response refused = f.run("tasks", "ADD AXIOM", "Import(<http://127.0.0.1:" + listener.getLocalPort()
                    + "/x.owl>) Import(<" + secret().toUri() + ">) SubClassOf(:Navigation :Errand)");
            assertFails(refused, 208);
            assertTrue(refused.errorDescription().contains("Import"), refused.errorDescription());
            org.junit.jupiter.api.Assertions.assertThrows(java.net.SocketTimeoutException.class, listener::accept);
        }
    }

    @Test
    void aFileThatIsNoOntologySaysSoAndNamesTheSyntaxesTried() throws IOException {
        Path notes = Files.writeString(scratch.resolve("notes.owl"), "shopping list: milk, bread\n");
        Response refused = load(fixture(false, false), "notes", notes);
        assertFails(refused, 209);
        String description = refused.errorDescription();
        assertTrue(description.contains("not an ontology in any supported syntax"), description);
        for (String syntax : List.of("RDF/XML", "OWL/XML", "Functional", "Turtle", "Manchester")) {
            assertTrue(description.contains(syntax), description);
        }
        assertFalse(description.contains("HDT") || description.contains("Exception"), description);
        Path turtle = Files.writeString(scratch.resolve("typo.ttl"), "@prefix : <http://x#> .\n:a :b \"unclosed .\n");
        String typo = load(fixture(false, false), "typo", turtle).errorDescription();
        assertTrue(typo.startsWith("could not parse") && typo.contains("as Turtle"), typo);
    }

    /** Web loading on: a local HTTP server stands in for the web. */
    @Test
    void withWebLoadingOnImportsAndLoadsFollowOnlyWebRedirects() throws IOException {
        Path secret = secret();
        HttpServer server = HttpServer.create(new InetSocketAddress("127.0.0.1", 0), 0);
        String base = "http://127.0.0.1:" + server.getAddress().getPort();
        server.createContext("/upper.owl", exchange -> send(exchange.getResponseBody(), exchange, 200, null,
                "Ontology(<" + base + "/upper.owl>\nDeclaration(Class(<" + base + "/upper#Task>))\n)\n"));
        server.createContext("/moved.owl", exchange -> send(exchange.getResponseBody(), exchange, 302,
                base + "/upper.owl", ""));
        server.createContext("/steal.owl", exchange -> send(exchange.getResponseBody(), exchange, 302,
                secret.toUri().toString(), ""));
        server.start();
        try {
            CoreFixture f = fixture(true, false);
            f.ok("web", "LOAD WEB", base + "/moved.owl", "", "false", "HERMIT", "false");
            f.ok("imports", "LOAD FILE", importer(scratch, base + "/moved.owl").toString(), "", "false", "HERMIT",
                    "false");
            assertTrue(f.ok("imports", "QUERY SPARQL", "ASK { <" + base + "/upper#Task> ?p ?o }").queriedObjects()
                    .contains("true"));
            assertFails(f.run("stolen", "LOAD WEB", base + "/steal.owl", "", "false", "HERMIT", "false"), 213);
            assertFails(f.run("stolen", "LOAD FILE", importer(scratch, base + "/steal.owl").toString(), "", "false",
                    "HERMIT", "false"), 213);
            assertFails(f.run("ftp", "LOAD FILE", importer(scratch, "ftp://127.0.0.1:9/x.owl").toString(), "",
                    "false", "HERMIT", "false"), 222);
        } finally {
            server.stop(0);
        }
    }

    private static void send(OutputStream body, com.sun.net.httpserver.HttpExchange exchange, int status,
                             String location, String text) throws IOException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        if (location != null) {
            exchange.getResponseHeaders().add("Location", location);
        }
        exchange.sendResponseHeaders(status, bytes.length == 0 ? -1 : bytes.length);
        try (body) {
            body.write(bytes);
        }
    }
}
