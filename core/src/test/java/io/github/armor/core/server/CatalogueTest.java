// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import io.github.armor.core.ArmorCore;
import io.github.armor.core.api.CoreConfig;
import io.github.armor.core.api.Directive;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.api.Setting;
import io.github.armor.core.command.Catalogue;
import io.github.armor.core.command.CommandGroup;
import io.github.armor.core.command.CommandKind;
import io.github.armor.core.command.CommandSpec;
import io.github.armor.core.command.CommandTable;
import io.github.armor.core.reference.ReasonerRegistry;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;

/** The catalogue the core prints, the registration point of command groups, settings and plugins. */
class CatalogueTest {
    @TempDir
    Path scratch;

    @Test
    void everyBuiltInCommandIsListedOnceWithItsKindSummaryAndAliases() {
        CommandTable table = CommandTable.standard();
        Set<String> keys = new HashSet<>();
        for (CommandSpec spec : table.catalogue()) {
            assertTrue(keys.add(spec.key()), spec.key());
            assertFalse(spec.summary().isBlank(), spec.key());
            assertEquals(spec, table.find(spec.key()).orElseThrow());
            spec.aliases().forEach(alias -> assertEquals(spec, table.find(alias).orElseThrow()));
        }
        assertEquals(CommandKind.DROPPING, table.find("DROP - -").orElseThrow().kind());
        assertEquals(CommandKind.MOUNTING, table.find("UNMOUNT - -").orElseThrow().kind());
        assertEquals(CommandKind.MANIPULATION, table.find("REASON - -").orElseThrow().kind());
        assertEquals(List.of("ADD MIN CARDINALITY"), table.find("ADD CARDINALITY MIN").orElseThrow().aliases());
    }

    @Test
    void theJsonListsCommandsExitCodesAndSettings() {
        JsonObject json = Catalogue.json(CommandTable.standard());
        assertEquals(CommandTable.standard().catalogue().size(), json.getAsJsonArray("commands").size());
        JsonObject drop = find(json, "commands", "key", "DROP - -");
        assertEquals("dropping", drop.get("kind").getAsString());
        assertEquals("", drop.getAsJsonArray("words").get(1).getAsString());
        JsonObject query = find(json, "commands", "key", "QUERY CLASS IND");
        assertEquals("most specific only",
                query.getAsJsonObject("args").getAsJsonArray("optional").get(0).getAsString());
        assertFalse(query.get("changes_ontology").getAsBoolean());
        assertEquals(ExitCode.values().length, json.getAsJsonArray("exit_codes").size());
        JsonObject lockWait = find(json, "settings", "key", "lock_wait_ms");
        assertEquals("integer", lockWait.get("type").getAsString());
        assertEquals(30_000, lockWait.get("default").getAsLong());
        assertTrue(lockWait.get("read_only").getAsBoolean());
        assertEquals(JsonParser.parseString(Catalogue.text(CommandTable.standard())), json);
    }

    @Test
    void aMisspeltOrMistypedSettingIsRefusedNotDefaulted() {
        IllegalArgumentException misspelt = assertThrows(IllegalArgumentException.class,
                () -> SettingsJson.parse(JsonParser.parseString("{\"lock_wait\": 5}").getAsJsonObject()));
        assertTrue(misspelt.getMessage().contains("unknown setting 'lock_wait'"), misspelt.getMessage());
        IllegalArgumentException mistyped = assertThrows(IllegalArgumentException.class,
                () -> SettingsJson.parse(JsonParser.parseString("{\"allowed_dirs\": \"/tmp\"}").getAsJsonObject()));
        assertTrue(mistyped.getMessage().contains("string_array"), mistyped.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> SettingsJson.parse(JsonParser.parseString("{\"lock_wait_ms\": 1.5}").getAsJsonObject()));
        Map<Setting, Object> values = SettingsJson.parse(JsonParser.parseString(
                "{\"lock_wait_ms\": 5, \"allowed_dirs\": [\"/tmp\"]}").getAsJsonObject());
        CoreConfig config = CoreConfig.fromSettings(values);
        assertEquals(5, config.lockWaitMs());
        assertEquals(List.of(Path.of("/tmp")), config.allowedDirs());
        assertEquals("PELLET", config.defaultReasoner());
        assertEquals(CoreConfig.Durability.NONE, config.durability());
    }

    @Test
    void aPluginJarAddsACommandGroupAndAReasonerFactory() throws Exception {
        Path plugins = Files.createDirectories(scratch.resolve("plugins"));
        PluginJars.build(scratch.resolve("build"), plugins.resolve("hello.jar"), Map.of(
                "example.HelloCommands", """
                        package example;
                        import io.github.armor.core.command.*;
                        import java.util.List;
                        public final class HelloCommands implements CommandGroup {
                            public void register(CommandTable table) {
                                table.command("QUERY HELLO").args("name").summary("greets")
                                        .global(c -> io.github.armor.core.api.Response.ok(true,
                                                List.of("hello " + c.arg(0))));
                            }
                        }
                        """,
                "example.TinyReasonerFactory", """
                        package example;
                        public final class TinyReasonerFactory extends org.semanticweb.HermiT.ReasonerFactory {}
                        """),
                Map.of(CommandGroup.class.getName(), "example.HelloCommands"),
                CommandGroup.class, OWLReasonerFactory.class, org.semanticweb.HermiT.ReasonerFactory.class);

        ClassLoader loader = Plugins.classLoader(List.of(plugins.toString()));
        CommandTable table = CommandTable.load(loader);
        assertEquals(CommandTable.standard().catalogue().size() + 1, table.catalogue().size());
        assertEquals("greets", find(Catalogue.json(table), "commands", "key", "QUERY HELLO -").get("summary")
                .getAsString());
        ArmorCore core = new ArmorCore(CoreConfig.defaults(scratch), table);
        Response hello = core.execute(Directive.of("c", "", "QUERY", "HELLO", "", "world"));
        assertEquals(List.of("hello world"), hello.queriedObjects());
        // Clients learn of the plugin's command from the running core.
        Response catalogue = core.execute(Directive.of("c", "", "GET", "CATALOGUE", ""));
        assertEquals(Catalogue.json(table), JsonParser.parseString(catalogue.queriedObjects().get(0)));
        assertEquals("greets", find(JsonParser.parseString(catalogue.queriedObjects().get(0)).getAsJsonObject(),
                "commands", "key", "QUERY HELLO -").get("summary").getAsString());

        assertThrows(RuntimeException.class,
                () -> ReasonerRegistry.canonicalName("example.TinyReasonerFactory", "HERMIT"));
        ReasonerRegistry.useClassLoader(loader);
        try {
            assertEquals("example.TinyReasonerFactory", ReasonerRegistry.canonicalName("example.TinyReasonerFactory",
                    "HERMIT"));
            assertEquals("example.TinyReasonerFactory", ReasonerRegistry.factory("example.TinyReasonerFactory")
                    .getClass().getName());
        } finally {
            ReasonerRegistry.useClassLoader(ReasonerRegistry.class.getClassLoader());
        }
    }

    @Test
    void aMissingPluginDirectoryIsRefusedNamingIt() {
        Path missing = scratch.resolve("none");
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> Plugins.classLoader(List.of(scratch.toString(), missing.toString())));
        assertTrue(refused.getMessage().contains(missing.toString()), refused.getMessage());
    }

    @Test
    void theJarsOfSeveralPluginDirectoriesAreLoadedAndBlankEntriesIgnored() throws Exception {
        for (String name : List.of("one", "two")) {
            String group = "example." + name + ".Commands";
            PluginJars.build(scratch.resolve("build-" + name), scratch.resolve(name).resolve(name + ".jar"), Map.of(
                    group, "package example." + name + ";\n"
                            + "public final class Commands implements io.github.armor.core.command.CommandGroup {\n"
                            + "    public void register(io.github.armor.core.command.CommandTable table) {\n"
                            + "        table.command(\"QUERY " + name.toUpperCase() + "\").summary(\"" + name
                            + "\").global(c -> c.ok());\n    }\n}\n"),
                    Map.of(CommandGroup.class.getName(), group), CommandGroup.class);
        }
        CommandTable table = CommandTable.load(Plugins.classLoader(List.of(
                scratch.resolve("one").toString(), " ", scratch.resolve("two").toString())));
        assertEquals("one.jar", table.find("QUERY ONE -").orElseThrow().origin());
        assertEquals("two.jar", table.find("QUERY TWO -").orElseThrow().origin());
        JsonObject json = Catalogue.json(table);
        assertEquals("two.jar", find(json, "commands", "key", "QUERY TWO -").get("origin").getAsString());
        assertEquals("core", find(json, "commands", "key", "QUERY IND CLASS").get("origin").getAsString());
    }

    private static JsonObject find(JsonObject json, String array, String field, String value) {
        for (JsonElement element : json.getAsJsonArray(array)) {
            if (element.getAsJsonObject().get(field).getAsString().equals(value)) {
                return element.getAsJsonObject();
            }
        }
        throw new AssertionError(value + " not in " + array);
    }
}
