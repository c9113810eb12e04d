// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.command;

import io.github.armor.core.api.Response;
import io.github.armor.core.spi.CommandBuilder;
import io.github.armor.core.spi.FaceAnswer;
import io.github.armor.core.spi.Handler;
import io.github.armor.core.spi.StateAnswer;

/** Where a plugin's {@link io.github.armor.core.spi.CommandGroup} registers: the core's table, seen through the SPI. */
final class PluginTable implements io.github.armor.core.spi.CommandTable {
    private final CommandTable table;

    PluginTable(CommandTable table) {
        this.table = table;
    }

    @Override
    public CommandBuilder command(String words) {
        return new Builder(table.command(words));
    }

    /** A plugin's handler as the core runs it; its class loader is the one the plugin's thread gets. */
    record Adapted(Handler handler) implements CommandSpec.Handler {
        @Override
        public Response run(CommandContext context) {
            return handler.run(new PluginContext(context));
        }

        ClassLoader loader() {
            return handler.getClass().getClassLoader();
        }
    }

    private record Builder(CommandTable.Builder builder) implements CommandBuilder {
        @Override
        public CommandBuilder alias(String words) {
            builder.alias(words);
            return this;
        }

        @Override
        public CommandBuilder args(String... names) {
            builder.args(names);
            return this;
        }

        @Override
        public CommandBuilder optional(String... names) {
            builder.optional(names);
            return this;
        }

        @Override
        public CommandBuilder variadic() {
            builder.variadic();
            return this;
        }

        @Override
        public CommandBuilder emptySurplusIgnored() {
            builder.emptySurplusIgnored();
            return this;
        }

        @Override
        public CommandBuilder summary(String text) {
            builder.summary(text);
            return this;
        }

        @Override
        public CommandBuilder face(String method, FaceAnswer answer, String... parameters) {
            builder.face(method, Face.Answer.valueOf(answer.name()), parameters);
            return this;
        }

        @Override
        public CommandBuilder whileBusy(StateAnswer source) {
            builder.whileBusy(new PluginStateSource(source));
            return this;
        }

        @Override
        public CommandBuilder subscribedAs(String words) {
            builder.subscribedAs(words);
            return this;
        }

        @Override
        public void query(Handler handler) {
            builder.query(new Adapted(handler));
        }

        @Override
        public void manipulation(Handler handler) {
            builder.manipulation(new Adapted(handler));
        }

        @Override
        public void onReference(Handler handler) {
            builder.onReference(new Adapted(handler));
        }

        @Override
        public void global(Handler handler) {
            builder.global(new Adapted(handler));
        }
    }
}
