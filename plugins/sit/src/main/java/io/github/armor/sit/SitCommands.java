// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.sit;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.api.Response;
import io.github.armor.core.spi.CommandGroup;
import io.github.armor.core.spi.CommandTable;
import io.github.armor.core.spi.Context;
import io.github.armor.core.spi.FaceAnswer;
import io.github.armor.core.spi.Knowledge;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyChange;
import org.semanticweb.owlapi.reasoner.OWLReasonerFactory;
import org.semanticweb.owlapi.search.EntitySearcher;

/**
 * The scene commands (docs/scenes.md), and the one place this plugin meets the core: every core
 * type it uses is named in this file, so a change of the core's plugin interface is a change here
 * only. SIT SCENE recognises a scene and learns it when new, as one journaled change of its
 * reference; QUERY SIT SCENES lists the learned classes in the reasoner's hierarchy; QUERY SIT
 * RECENT shows the last scenes with their recognitions explained.
 */
public final class SitCommands implements CommandGroup {
    private final RecentScenes recent = new RecentScenes();

    @Override
    public void register(CommandTable table) {
        table.command("SIT SCENE").args("learning_threshold", "position_threshold", "axis_threshold", "elements")
                .summary("recognise a scene of primitives (elements: 'TYPE x y z [ax ay az]; ...') under the"
                        + " scene classes learned so far, and learn it as a new class unless one is more similar"
                        + " than learning_threshold (docs/scenes.md)")
                .manipulation(this::scene);
        table.command("QUERY SIT SCENES")
                .summary("the learned scene classes: definition in words, cardinality, the scenes each contains"
                        + " (one JSON object each)")
                .face("scene_classes", FaceAnswer.EXPRESSIONS)
                .query(c -> c.ok(SceneHierarchy.of(new CoreReference(c)).stream()
                        .map(p -> SceneJson.sceneClass(p.owlClass(), p.definition(), p.parents(), p.equivalents(),
                                c::render).toString())
                        .toList()));
        table.command("QUERY SIT RECENT")
                .summary("the last scenes of this reference in this session, each recognition explained (one JSON"
                        + " object each, newest first)")
                .face("recent_scenes", FaceAnswer.EXPRESSIONS)
                .query(c -> c.ok(recent.of(c.knowledge().identity()).stream().map(Object::toString).toList()));
    }

    private Response scene(Context c) {
        SceneTeacher.Outcome outcome;
        try {
            double threshold = Scene.learningThreshold(c.arg(0));
            Scene scene = Scene.parse(c.arg(3), c.arg(1), c.arg(2));
            outcome = SceneTeacher.evaluate(new CoreReference(c), scene, threshold);
        } catch (InvalidScene e) {
            throw new ArmorException(switch (e.kind()) {
                case SHAPE -> ExitCode.WRONG_ARGUMENTS;
                case VALUE -> ExitCode.BAD_DATA_TYPE;
                case TOO_LARGE -> ExitCode.TOO_LARGE;
                case INCONSISTENT -> ExitCode.INCONSISTENT;
            }, e.getMessage() + "; nothing changed");
        }
        if (!c.replaying()) {
            recent.record(c.knowledge().identity(), SceneJson.outcome(outcome, c.directive().clientName(),
                    System.currentTimeMillis(), c::render));
        }
        List<String> answer = new ArrayList<>();
        outcome.learned().ifPresent(learned -> answer.add("learned " + c.render(learned)));
        for (SceneTeacher.Recognition recognition : outcome.recognitions()) {
            answer.add("recognised " + c.render(recognition.owlClass()) + " " + recognition.similarity());
        }
        return c.ok(answer);
    }

    /** A reference as the scene logic sees it, over the core's plugin context. */
    private static final class CoreReference implements SceneReference {
        private final Context context;
        private final Knowledge knowledge;

        CoreReference(Context context) {
            this.context = context;
            this.knowledge = context.knowledge();
        }

        @Override
        public OWLOntology ontology() {
            return knowledge.ontology();
        }

        @Override
        public OWLDataFactory factory() {
            return knowledge.factory();
        }

        @Override
        public IRI iri(EntityType<?> type, String name) {
            return knowledge.iri(type, name);
        }

        @Override
        public void enact(List<OWLOntologyChange> changes) {
            context.enact(changes);
        }

        @Override
        public Set<OWLClass> types(OWLNamedIndividual individual) {
            knowledge.synchroniseReasoner();
            return named(EntitySearcher.getTypes(individual, knowledge.closure()),
                    knowledge.inferred(r -> r.getTypes(individual, false).entities()));
        }

        @Override
        public boolean consistent() {
            return knowledge.consistent();
        }

        @Override
        public OWLReasonerFactory reasonerFactory() {
            return knowledge.reasonerFactory();
        }

        @Override
        public Object identity() {
            return knowledge.identity();
        }

        @Override
        public Set<OWLClass> superClasses(OWLClass owlClass) {
            return named(EntitySearcher.getSuperClasses(owlClass, knowledge.closure()),
                    knowledge.inferred(r -> r.getSuperClasses(owlClass, false).entities()));
        }

        @Override
        public Set<OWLClass> equivalentClasses(OWLClass owlClass) {
            Set<OWLClass> equivalents = named(EntitySearcher.getEquivalentClasses(owlClass, knowledge.closure()),
                    knowledge.inferred(r -> r.getEquivalentClasses(owlClass).entities()));
            equivalents.remove(owlClass);
            return equivalents;
        }

        /** The named classes among the asserted ones, then the inferred ones, each once. */
        private static Set<OWLClass> named(Stream<OWLClassExpression> asserted, Stream<OWLClass> inferred) {
            return Stream.concat(asserted.filter(e -> !e.isAnonymous()).map(OWLClassExpression::asOWLClass), inferred)
                    .collect(Collectors.toCollection(LinkedHashSet::new));
        }
    }
}
