// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.server;

import io.github.armor.core.api.Directive;
import io.github.armor.core.api.Response;
import io.github.armor.core.log.DirectiveLog;
import java.util.List;
import java.util.logging.Level;
import org.slf4j.LoggerFactory;

/** Logs one line of each kind as the core process does, for {@link ProcessLogTest} to read. */
public final class ProcessLogProbe {
    private ProcessLogProbe() {}

    public static void main(String[] args) throws InterruptedException {
        ProcessLog.install();
        java.util.logging.Logger reasoner = java.util.logging.Logger.getLogger("openllet.core.KnowledgeBaseImpl");
        reasoner.log(Level.INFO, "classified {} classes in {} ms", new Object[] {42, 7});
        reasoner.log(Level.WARNING, "ignoring unsupported axiom {0}", "SWRL built-in");
        LoggerFactory.getLogger("io.github.armor.core.ArmorCore").info("restored reference 'r'");
        LoggerFactory.getLogger("io.github.armor.core.ArmorCore").debug("core detail");
        LoggerFactory.getLogger("org.semanticweb.owlapi.Parser").info("library chatter");
        DirectiveLog directives = new DirectiveLog(System.err);
        directives.screen(true);
        directives.record(new Directive("c", "r", "QUERY", "IND", "CLASS", List.of("Room")),
                Response.ok(true, List.of()));
        Thread.sleep(500);
    }
}
