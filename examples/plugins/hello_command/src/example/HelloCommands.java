// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package example;

import io.github.armor.core.api.Response;
import io.github.armor.core.spi.CommandGroup;
import io.github.armor.core.spi.CommandTable;
import io.github.armor.core.spi.Context;
import io.github.armor.core.spi.FaceAnswer;
import java.util.List;
import org.semanticweb.owlapi.model.AddAxiom;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.OWLClass;

/**
 * A tiny plugin of the knowledge core (docs/extending.md): a command that needs no reference,
 * one that changes a reference and one that asks the reasoner. Built into a jar with
 * examples/plugins/build.sh; a node loads it from a directory of its plugin_dirs parameter.
 * It uses only the core's plugin interface (io.github.armor.core.spi) and its api.
 */
public final class HelloCommands implements CommandGroup {
    @Override
    public void register(CommandTable table) {
        table.command("QUERY HELLO").args("name").summary("greets someone")
                .global(c -> Response.ok(true, List.of("hello " + c.arg(0))));
        // A manipulation: refused under another client's mount, journaled, undone with its list.
        // Its face gives Python clients a method, ref.greet('kitchen'), found in the node's catalogue.
        table.command("ADD GREETING").args("ind").summary("asserts that the individual was greeted")
                .face("greet", FaceAnswer.NONE, "individual")
                .manipulation(c -> c.change(List.of(new AddAxiom(c.knowledge().ontology(),
                        c.knowledge().factory().getOWLClassAssertionAxiom(greeted(c), c.individual(0))))));
        // A query: answered from what the reasoner infers, like the built-in ones; while a writer
        // holds the reference, from the state its reasoner last published instead of waiting.
        table.command("QUERY GREETING").summary("who was greeted, as the reasoner concludes")
                .face("greeted", FaceAnswer.ENTITIES)
                .whileBusy(state -> state.known(EntityType.CLASS, "Greeted")
                        .map(greeted -> state.render(state.instances(greeted).stream())))
                .query(c -> c.ok(c.render(c.knowledge().instances(greeted(c), false).stream())));
        // The same people as sentences; a subscription to it follows them (QUERY GREETING).
        table.command("QUERY GREETING SENTENCES").summary("a sentence for each individual greeted")
                .face("greeting_sentences", FaceAnswer.VALUES).subscribedAs("QUERY GREETING")
                .query(c -> c.ok(c.knowledge().instances(greeted(c), false).stream()
                        .map(individual -> "hello " + individual.getIRI().getShortForm()).sorted().toList()));
    }

    private static OWLClass greeted(Context c) {
        return c.knowledge().factory().getOWLClass(c.knowledge().iri(EntityType.CLASS, "Greeted"));
    }
}
