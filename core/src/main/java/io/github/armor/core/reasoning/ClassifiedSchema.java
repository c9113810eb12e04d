// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reasoning;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.semanticweb.owlapi.model.AxiomType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.reasoner.Node;
import org.semanticweb.owlapi.reasoner.NodeSet;
import org.semanticweb.owlapi.reasoner.OWLReasoner;
import org.semanticweb.owlapi.reasoner.impl.OWLClassNode;
import org.semanticweb.owlapi.reasoner.impl.OWLClassNodeSet;

/**
 * The class hierarchy of a schema, classified once by a reasoner of the reference's kind on the
 * schema alone and kept while the schema stays the same: an ABox change does not classify an
 * upper ontology's classes again, and a restart reads it back from the checkpoint's sidecar
 * instead of classifying ({@link #toJson}).
 *
 * <p>Why the schema alone gives the whole ontology's hierarchy: in a consistent ontology whose
 * schema names no individual, a model of the schema with an instance of C and not of D, joined
 * disjointly to a model of the whole ontology, is a model of the whole ontology; so C is below D
 * in the whole ontology exactly when it is in the schema. A schema that names individuals
 * (nominals, as SOMA's ExecutionStateRegion = {Active, Cancelled, ...}) is classified with the
 * assertions about those individuals; the argument then holds as long as no other individual is
 * asserted a class or property of an axiom that names individuals, or related to one of them
 * ({@link #covers}); otherwise the caller asks a reasoner on the whole ontology, as before.
 *
 * <p>Immutable: read from any thread.
 */
public final class ClassifiedSchema {
    /** Kept between references and reasoners of one core: the same schema loaded again is not classified again. */
    private static final int KEPT = 16;
    private static final Map<String, ClassifiedSchema> KNOWN = Collections.synchronizedMap(
            new LinkedHashMap<>(16, 0.75f, true) {
                @Override
                protected boolean removeEldestEntry(Map.Entry<String, ClassifiedSchema> eldest) {
                    return size() > KEPT;
                }
            });

    private static final java.util.concurrent.atomic.AtomicLong CLASSIFICATIONS = new java.util.concurrent.atomic.AtomicLong();

    private final String digest;
    private final boolean consistent;
    private final long classificationNanos;
    // Equivalence nodes; node 0 holds owl:Thing, node 1 owl:Nothing and the unsatisfiable classes.
    private final List<Set<OWLClass>> nodes;
    private final Map<OWLClass, Integer> nodeOf;
    private final List<int[]> parents;
    private final List<int[]> children;

    private ClassifiedSchema(String digest, boolean consistent, long classificationNanos, List<Set<OWLClass>> nodes,
                             List<int[]> parents) {
        this.digest = digest;
        this.consistent = consistent;
        this.classificationNanos = classificationNanos;
        this.nodes = nodes;
        this.parents = parents;
        this.nodeOf = new HashMap<>();
        for (int i = 0; i < nodes.size(); i++) {
            for (OWLClass owlClass : nodes.get(i)) {
                nodeOf.put(owlClass, i);
            }
        }
        List<List<Integer>> below = new ArrayList<>();
        nodes.forEach(node -> below.add(new ArrayList<>()));
        for (int i = 0; i < parents.size(); i++) {
            for (int parent : parents.get(i)) {
                below.get(parent).add(i);
            }
        }
        this.children = below.stream().map(list -> list.stream().mapToInt(Integer::intValue).toArray()).toList();
    }

    /** What a schema is made of, as classification sees it; its digest names the classification. */
    public record Input(String digest, List<OWLAxiom> axioms, Set<OWLEntity> nominalSignature,
                        Set<OWLNamedIndividual> schemaIndividuals) {}

    /**
     * The schema of an ontology: its logical axioms that are not assertions (SWRL rules only when
     * the schema names individuals), a declaration of every class, property and datatype, and the
     * assertions about individuals the schema names; with the reasoner's name, they make the digest.
     */
    public static Input inputOf(OWLOntology ontology, String reasonerName) {
        OWLDataFactory data = ontology.getOWLOntologyManager().getOWLDataFactory();
        List<OWLAxiom> schema = new ArrayList<>();
        Set<OWLNamedIndividual> named = new HashSet<>();
        Set<OWLEntity> nominalSignature = new HashSet<>();
        AxiomType.AXIOM_TYPES.stream()
                .filter(type -> type.isLogical() && !AxiomType.ABoxAxiomTypes.contains(type))
                .flatMap(type -> ontology.axioms(type, Imports.INCLUDED).map(OWLAxiom.class::cast))
                .forEach(axiom -> {
                    schema.add(axiom);
                    if (axiom.individualsInSignature().findAny().isPresent()) {
                        axiom.individualsInSignature().forEach(named::add);
                        axiom.signature().filter(e -> !e.isOWLNamedIndividual() && !e.isBuiltIn())
                                .forEach(nominalSignature::add);
                    }
                });
        if (!named.isEmpty()) {
            ontology.axioms(Imports.INCLUDED).filter(axiom -> axiom.isOfType(AxiomType.ABoxAxiomTypes)
                            && axiom.individualsInSignature().anyMatch(named::contains))
                    .forEach(schema::add);
        } else {
            // A DL-safe rule binds named individuals only, and a schema naming none has none to
            // bind: rules change nothing there, and HermiT refuses those with built-ins outright.
            schema.removeIf(axiom -> axiom.isOfType(AxiomType.SWRL_RULE));
        }
        ontology.signature(Imports.INCLUDED).filter(entity -> !entity.isOWLNamedIndividual() && !entity.isBuiltIn())
                .map(data::getOWLDeclarationAxiom).forEach(schema::add);
        List<String> lines = new ArrayList<>(schema.stream().distinct().map(OWLAxiom::toString).toList());
        Collections.sort(lines);
        return new Input(digest(reasonerName, lines), schema.stream().distinct().toList(),
                Set.copyOf(nominalSignature), Set.copyOf(named));
    }

    /** The classification of this input made or read earlier in this core, if any. */
    public static ClassifiedSchema known(Input input) {
        return KNOWN.get(input.digest());
    }

    /** How many classifications this core has made (a kept one is not counted): what tests watch. */
    public static long classifications() {
        return CLASSIFICATIONS.get();
    }

    /** Forgets every kept classification (a restarted core starts without them; tests play one). */
    public static void forgetKept() {
        KNOWN.clear();
    }

    /** Keeps a classification read from a checkpoint's sidecar, for the reference restored next. */
    public static void remember(ClassifiedSchema schema) {
        KNOWN.put(schema.digest, schema);
    }

    /**
     * Classifies with {@code reasoner}, made on the input's axioms alone; a schema found
     * inconsistent has no hierarchy (every class is unsatisfiable, nothing to keep).
     */
    public static ClassifiedSchema classify(Input input, OWLReasoner reasoner) {
        CLASSIFICATIONS.incrementAndGet();
        long start = System.nanoTime();
        boolean consistent = reasoner.isConsistent();
        List<Set<OWLClass>> nodes = new ArrayList<>();
        List<int[]> parents = new ArrayList<>();
        if (consistent) {
            reasoner.precomputeInferences(org.semanticweb.owlapi.reasoner.InferenceType.CLASS_HIERARCHY);
            Map<Node<OWLClass>, Integer> index = new HashMap<>();
            Node<OWLClass> top = reasoner.getTopClassNode();
            Node<OWLClass> bottom = reasoner.getBottomClassNode();
            index.put(top, 0);
            nodes.add(top.entities().collect(java.util.stream.Collectors.toSet()));
            index.put(bottom, 1);
            nodes.add(bottom.entities().collect(java.util.stream.Collectors.toSet()));
            ArrayDeque<Node<OWLClass>> pending = new ArrayDeque<>(List.of(top));
            Map<Integer, Set<Integer>> above = new HashMap<>();
            while (!pending.isEmpty()) {
                Node<OWLClass> node = pending.poll();
                int parent = index.get(node);
                for (Node<OWLClass> child : reasoner.getSubClasses(node.getRepresentativeElement(), true)) {
                    if (child.isBottomNode()) {
                        continue;
                    }
                    Integer number = index.get(child);
                    if (number == null) {
                        number = nodes.size();
                        index.put(child, number);
                        nodes.add(child.entities().collect(java.util.stream.Collectors.toSet()));
                        pending.add(child);
                    }
                    above.computeIfAbsent(number, k -> new HashSet<>()).add(parent);
                }
            }
            for (int i = 0; i < nodes.size(); i++) {
                parents.add(i == 0 ? new int[0] : above.getOrDefault(i, Set.of()).stream().mapToInt(Integer::intValue)
                        .toArray());
            }
        }
        ClassifiedSchema classified = new ClassifiedSchema(input.digest(), consistent, System.nanoTime() - start,
                nodes, parents);
        remember(classified);
        return classified;
    }

    public String digest() {
        return digest;
    }

    /** Whether the schema alone is consistent (an ontology without individuals then is). */
    public boolean consistent() {
        return consistent;
    }

    /** How long classifying took when it was done (a kept one took it earlier, elsewhere). */
    public long classificationNanos() {
        return classificationNanos;
    }

    /** How many named classes the hierarchy places (owl:Thing and owl:Nothing included). */
    public int classCount() {
        return nodeOf.size();
    }

    /**
     * Whether the hierarchy answers for an ontology with this ABox: no assertion about an
     * individual the schema does not name uses an entity of an axiom that names individuals, or
     * relates such an individual to one the schema names.
     */
    public static boolean covers(Input input, Stream<OWLAxiom> aboxAxioms) {
        if (input.schemaIndividuals().isEmpty()) {
            return true;
        }
        return aboxAxioms.noneMatch(axiom -> escapes(input, axiom));
    }

    /** Whether one ABox axiom takes the classification outside what {@link #covers} allows. */
    public static boolean escapes(Input input, OWLAxiom axiom) {
        if (input.schemaIndividuals().isEmpty() || !axiom.isOfType(AxiomType.ABoxAxiomTypes)) {
            return false;
        }
        List<OWLNamedIndividual> about = axiom.individualsInSignature().toList();
        boolean outsider = about.stream().anyMatch(i -> !input.schemaIndividuals().contains(i))
                || axiom.anonymousIndividuals().findAny().isPresent();
        if (!outsider) {
            return false;
        }
        return about.stream().anyMatch(input.schemaIndividuals()::contains)
                || axiom.signature().anyMatch(input.nominalSignature()::contains);
    }

    public NodeSet<OWLClass> superClasses(OWLClass owlClass, boolean direct) {
        return related(owlClass, direct, parents);
    }

    public NodeSet<OWLClass> subClasses(OWLClass owlClass, boolean direct) {
        return related(owlClass, direct, children);
    }

    /** The most specific of some classes of an individual (each with every class above it), by node. */
    public NodeSet<OWLClass> mostSpecific(NodeSet<OWLClass> all) {
        Set<OWLClass> above = new HashSet<>();
        all.entities().forEach(owlClass -> superClasses(owlClass, false).entities().forEach(above::add));
        OWLClassNodeSet direct = new OWLClassNodeSet();
        all.entities().filter(owlClass -> !above.contains(owlClass))
                .forEach(owlClass -> direct.addNode(equivalentClasses(owlClass)));
        return direct;
    }

    public Node<OWLClass> equivalentClasses(OWLClass owlClass) {
        Integer node = nodeOf.get(owlClass);
        return new OWLClassNode(node == null ? Set.of(owlClass) : nodes.get(node));
    }

    public Node<OWLClass> topNode() {
        return new OWLClassNode(nodes.get(0));
    }

    public Node<OWLClass> bottomNode() {
        return new OWLClassNode(nodes.get(1));
    }

    public boolean isSatisfiable(OWLClass owlClass) {
        Integer node = nodeOf.get(owlClass);
        return node == null || node != 1;
    }

    /**
     * The nodes above (or below) a class. A class the schema does not mention (asserted of an
     * individual only) sits directly below owl:Thing with nothing but owl:Nothing below it.
     */
    private NodeSet<OWLClass> related(OWLClass owlClass, boolean direct, List<int[]> edges) {
        OWLClassNodeSet answer = new OWLClassNodeSet();
        Integer start = nodeOf.get(owlClass);
        boolean up = edges == parents;
        if (start == null) {
            answer.addNode(up ? topNode() : bottomNode());
            return answer;
        }
        if (start == 1) {
            // Below owl:Nothing is nothing; above it is every class, unsatisfiable ones aside.
            if (up) {
                for (int i = 0; i < nodes.size(); i++) {
                    if (i != 1 && (!direct || children.get(i).length == 0)) {
                        answer.addNode(new OWLClassNode(nodes.get(i)));
                    }
                }
            }
            return answer;
        }
        Set<Integer> seen = new HashSet<>();
        ArrayDeque<Integer> pending = new ArrayDeque<>();
        for (int next : edges.get(start)) {
            pending.add(next);
        }
        if (!up && (edges.get(start).length == 0)) {
            pending.add(1);
        }
        while (!pending.isEmpty()) {
            int node = pending.poll();
            if (!seen.add(node)) {
                continue;
            }
            answer.addNode(new OWLClassNode(nodes.get(node)));
            if (direct) {
                continue;
            }
            for (int next : node == 1 ? new int[0] : edges.get(node)) {
                pending.add(next);
            }
            if (!up && node != 1 && edges.get(node).length == 0) {
                pending.add(1);
            }
        }
        return answer;
    }

    /** The sidecar's content: digest, consistency, time, and each node with its parents, by IRI. */
    public JsonObject toJson() {
        JsonObject json = new JsonObject();
        json.addProperty("digest", digest);
        json.addProperty("consistent", consistent);
        json.addProperty("classification_ms", classificationNanos / 1_000_000);
        JsonArray all = new JsonArray();
        for (int i = 0; i < nodes.size(); i++) {
            JsonObject node = new JsonObject();
            JsonArray classes = new JsonArray();
            nodes.get(i).stream().map(c -> c.getIRI().toString()).sorted().forEach(classes::add);
            node.add("classes", classes);
            JsonArray up = new JsonArray();
            for (int parent : parents.get(i)) {
                up.add(parent);
            }
            node.add("parents", up);
            all.add(node);
        }
        json.add("nodes", all);
        return json;
    }

    /** A classification written by {@link #toJson}; classes are made with {@code data}. */
    public static ClassifiedSchema fromJson(JsonObject json, OWLDataFactory data) {
        List<Set<OWLClass>> nodes = new ArrayList<>();
        List<int[]> parents = new ArrayList<>();
        for (JsonElement element : json.getAsJsonArray("nodes")) {
            JsonObject node = element.getAsJsonObject();
            Set<OWLClass> classes = new HashSet<>();
            node.getAsJsonArray("classes").forEach(iri -> classes.add(data.getOWLClass(IRI.create(iri.getAsString()))));
            nodes.add(classes);
            JsonArray up = node.getAsJsonArray("parents");
            int[] numbers = new int[up.size()];
            for (int i = 0; i < numbers.length; i++) {
                numbers[i] = up.get(i).getAsInt();
            }
            parents.add(numbers);
        }
        return new ClassifiedSchema(json.get("digest").getAsString(), json.get("consistent").getAsBoolean(),
                json.get("classification_ms").getAsLong() * 1_000_000, nodes, parents);
    }

    private static String digest(String reasonerName, List<String> lines) {
        try {
            MessageDigest sha = MessageDigest.getInstance("SHA-256");
            sha.update(reasonerName.getBytes(StandardCharsets.UTF_8));
            for (String line : lines) {
                sha.update((byte) '\n');
                sha.update(line.getBytes(StandardCharsets.UTF_8));
            }
            return HexFormat.of().formatHex(sha.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is missing from this Java", e);
        }
    }
}
