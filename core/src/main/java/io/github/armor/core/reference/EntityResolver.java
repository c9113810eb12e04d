// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.reference;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.TreeMap;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentSkipListMap;
import java.util.function.Predicate;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.parameters.Imports;

/**
 * Finds the entity an argument names (contract section 3): {@code <full IRI>}, a bare http(s) IRI,
 * {@code prefix:Name} with the document's prefixes, or a plain name. A plain name takes the
 * reference's default namespace, unless that entity does not exist and exactly one entity of the
 * same kind ends in {@code #Name} or {@code /Name}: ontologies edited in Protégé often mix namespaces.
 */
public final class EntityResolver {
    // Names looked at on each side of an unknown name, in each of the two orders, for "did you mean".
    private static final int NEIGHBOURS = 8;
    private static final Pattern PLAIN_NAME = Pattern.compile("[^\\s<>\"{}|^`\\\\]+");
    private static final Pattern ABSOLUTE_IRI = Pattern.compile("[A-Za-z][A-Za-z0-9+.-]*:[^\\s<>\"{}|^`\\\\\\p{Cntrl}]*");

    private final OWLOntology ontology;
    private final OWLDataFactory factory;
    private final String defaultNamespace;
    private final Map<String, String> prefixes;
    // Short name (after the last '#' or '/') to every IRI ever seen with it. Never pruned:
    // lookups check the live signature, so an entity removed since is simply not found.
    private final Map<String, Set<IRI>> byShortName = new ConcurrentHashMap<>();
    // Short forms lower-cased, and the same reversed, to their IRIs, sorted: "did you mean" looks
    // only at a name's neighbours in both orders (see describeUnknown).
    private final NavigableMap<String, Set<IRI>> byLowerShortForm = new ConcurrentSkipListMap<>();
    private final NavigableMap<String, Set<IRI>> byReversedShortForm = new ConcurrentSkipListMap<>();

    public EntityResolver(OWLOntology ontology, String defaultNamespace, Map<String, String> prefixes) {
        this.ontology = ontology;
        this.factory = ontology.getOWLOntologyManager().getOWLDataFactory();
        this.defaultNamespace = defaultNamespace;
        this.prefixes = Map.copyOf(prefixes);
        ontology.signature(Imports.INCLUDED).forEach(this::index);
        ontology.getOWLOntologyManager().addOntologyChangeListener(changes -> changes.stream()
                .filter(change -> change.isAddAxiom() && change.getOntology() == ontology)
                .forEach(change -> change.getAxiom().signature().forEach(this::index)));
    }

    private void index(OWLEntity entity) {
        String iri = entity.getIRI().toString();
        int cut = Math.max(iri.lastIndexOf('#'), iri.lastIndexOf('/'));
        byShortName.computeIfAbsent(iri.substring(cut + 1), k -> ConcurrentHashMap.newKeySet()).add(entity.getIRI());
        String lower = entity.getIRI().getShortForm().toLowerCase(java.util.Locale.ROOT);
        byLowerShortForm.computeIfAbsent(lower, k -> ConcurrentHashMap.newKeySet()).add(entity.getIRI());
        byReversedShortForm.computeIfAbsent(reversed(lower), k -> ConcurrentHashMap.newKeySet()).add(entity.getIRI());
    }

    public String defaultNamespace() {
        return defaultNamespace;
    }

    /** Prefix name (without the colon) to namespace, as the ontology document declares them. */
    public Map<String, String> prefixes() {
        return prefixes;
    }

    public <E extends OWLEntity> E entity(EntityType<E> type, String argument) {
        return factory.getOWLEntity(type, iri(type, argument));
    }

    /** The entity an argument names, resolved against the signature {@code inSignature} (see {@link #iri}). */
    public <E extends OWLEntity> E entity(EntityType<E> type, String argument, Predicate<OWLEntity> inSignature) {
        return factory.getOWLEntity(type, iri(type, argument, inSignature));
    }

    /** The IRI an argument names for an entity of the given kind. */
    public IRI iri(EntityType<?> type, String argument) {
        return iri(type, argument, entity -> ontology.containsEntityInSignature(entity, Imports.INCLUDED));
    }

    /**
     * The same, with the signature given by {@code inSignature}: a reader that may not touch the
     * live ontology (it answers from a kept state while a writer holds the reference) passes that
     * state's signature.
     */
    public IRI iri(EntityType<?> type, String argument, Predicate<OWLEntity> inSignature) {
        String name = argument.trim();
        if (name.isEmpty()) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "empty " + kind(type) + " name");
        }
        if (name.startsWith("<") || name.endsWith(">")) {
            if (!(name.startsWith("<") && name.endsWith(">"))) {
                throw new ArmorException(ExitCode.BAD_SYNTAX, "unbalanced angle brackets in IRI '" + name + "'");
            }
            return absoluteIri(name.substring(1, name.length() - 1), name);
        }
        if (name.startsWith("http://") || name.startsWith("https://")) {
            return absoluteIri(name, name);
        }
        int colon = name.indexOf(':');
        if (colon >= 0) {
            String namespace = prefixes.get(name.substring(0, colon));
            if (namespace == null) {
                throw new ArmorException(ExitCode.BAD_SYNTAX, "unknown prefix '" + name.substring(0, colon)
                        + ":' in '" + name + "'; declared prefixes: " + String.join(", ", prefixes.keySet()));
            }
            return absoluteIri(namespace + name.substring(colon + 1), name);
        }
        if (!PLAIN_NAME.matcher(name).matches()) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "'" + name + "' is not a valid " + kind(type) + " name");
        }
        IRI inDefault = IRI.create(defaultNamespace + name);
        if (inSignature.test(factory.getOWLEntity(type, inDefault))) {
            return inDefault;
        }
        List<IRI> elsewhere = byShortName.getOrDefault(name, Set.of()).stream()
                .filter(iri -> inSignature.test(factory.getOWLEntity(type, iri)))
                .sorted().toList();
        if (elsewhere.size() == 1) {
            return elsewhere.get(0);
        }
        if (elsewhere.size() > 1) {
            throw new ArmorException(ExitCode.AMBIGUOUS_NAME, "the " + kind(type) + " name '" + name
                    + "' matches several entities: " + elsewhere.stream().map(i -> "<" + i + ">").toList()
                    + "; write the full IRI or prefix:Name");
        }
        return inDefault;
    }

    /**
     * Whether the reference knows the entity (built-ins always count as known): referring to an
     * unknown one creates it (ARMOR's rule), which a typo does silently.
     */
    public boolean knows(OWLEntity entity) {
        return entity.isBuiltIn() || ontology.containsEntityInSignature(entity, Imports.INCLUDED);
    }

    /** "individual 'alise' (did you mean alice?)": an unknown name and the known ones closest to it. */
    public String describeUnknown(EntityType<?> type, String argument) {
        String name = argument.trim();
        int cut = Math.max(name.lastIndexOf('#'), Math.max(name.lastIndexOf('/'), name.lastIndexOf(':')));
        String shortName = name.substring(cut + 1).replace(">", "");
        int limit = Math.max(1, Math.min(3, shortName.length() / 3));
        // Every ADD of a new individual asks this, so it must not visit every name (a scan of the
        // index took 83% of an ADD's time at 5,000 individuals). A name one typo away from another
        // keeps at least half of it as prefix or as suffix, so it sorts near it in one of the two
        // orders: the names around it in each are the candidates.
        String wanted = shortName.toLowerCase(java.util.Locale.ROOT);
        Map<IRI, String> candidates = new java.util.HashMap<>();
        neighbours(byLowerShortForm, wanted).forEach(iri -> candidates.put(iri,
                iri.getShortForm().toLowerCase(java.util.Locale.ROOT)));
        neighbours(byReversedShortForm, reversed(wanted)).forEach(iri -> candidates.put(iri,
                iri.getShortForm().toLowerCase(java.util.Locale.ROOT)));
        List<String> close = candidates.entrySet().stream()
                .filter(known -> Math.abs(known.getValue().length() - shortName.length()) <= limit)
                .map(known -> Map.entry(known.getKey(), editDistance(known.getValue(), wanted, limit)))
                .filter(scored -> scored.getValue() <= limit && ontology.containsEntityInSignature(
                        factory.getOWLEntity(type, scored.getKey()), Imports.INCLUDED))
                .map(scored -> Map.entry(scored.getKey().getShortForm(), scored.getValue()))
                .distinct()
                .sorted(Map.Entry.<String, Integer>comparingByValue().thenComparing(Map.Entry.comparingByKey()))
                .limit(3).map(Map.Entry::getKey).toList();
        return kind(type) + " '" + name + "'" + (close.isEmpty() ? "" : " (did you mean " + String.join(", ", close)
                + "?)");
    }

    /** The IRIs of the {@value #NEIGHBOURS} keys on each side of {@code key} in {@code sorted}. */
    private static List<IRI> neighbours(NavigableMap<String, Set<IRI>> sorted, String key) {
        List<IRI> found = new java.util.ArrayList<>();
        sorted.headMap(key, false).descendingMap().values().stream().limit(NEIGHBOURS).forEach(found::addAll);
        sorted.tailMap(key, true).values().stream().limit(NEIGHBOURS).forEach(found::addAll);
        return found;
    }

    private static String reversed(String text) {
        return new StringBuilder(text).reverse().toString();
    }

    /**
     * The edit distance of a and b when it is at most {@code limit}, else {@code limit + 1}.
     * Only the cells within {@code limit} of the diagonal can hold such a distance, so only they
     * are computed: two names of 100,000 characters cost 100,000 x (2 limit + 1) steps, not
     * 10^10 (a client's hostile name made a reference's every unknown-name check take minutes).
     */
    public static int editDistance(String a, String b, int limit) {
        int n = a.length();
        int m = b.length();
        int over = limit >= Integer.MAX_VALUE - 1 ? Integer.MAX_VALUE - 1 : limit + 1;
        if (Math.abs(n - m) > limit) {
            return over;
        }
        int[] previous = new int[m + 2];
        int[] current = new int[m + 2];
        for (int j = 0; j <= m; j++) {
            previous[j] = Math.min(j, over);
        }
        previous[m + 1] = over;
        for (int i = 1; i <= n; i++) {
            int from = (int) Math.max(1, (long) i - limit);
            int to = (int) Math.min(m, (long) i + limit);
            current[0] = Math.min(i, over);
            current[from - 1] = from == 1 ? current[0] : over;
            int rowBest = current[from - 1];
            for (int j = from; j <= to; j++) {
                int diagonal = previous[j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                current[j] = Math.min(over, Math.min(diagonal, Math.min(previous[j], current[j - 1]) + 1));
                rowBest = Math.min(rowBest, current[j]);
            }
            current[to + 1] = over;
            if (rowBest >= over) {
                return over;  // a row's least value never falls again
            }
            int[] swap = previous;
            previous = current;
            current = swap;
        }
        return previous[m];
    }

    /** An argument that must be an absolute IRI: a scheme, and none of the characters RFC 3987 leaves out. */
    static IRI absoluteIri(String text, String argument) {
        if (!ABSOLUTE_IRI.matcher(text).matches()) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "'" + argument + "' is not a valid absolute IRI");
        }
        return IRI.create(text);
    }

    static String kind(EntityType<?> type) {
        if (type == EntityType.NAMED_INDIVIDUAL) {
            return "individual";
        }
        if (type == EntityType.OBJECT_PROPERTY) {
            return "object property";
        }
        if (type == EntityType.DATA_PROPERTY) {
            return "data property";
        }
        return type.getPrintName().toLowerCase(java.util.Locale.ROOT);
    }

    /** Namespaces a document declares, keyed by prefix name without the trailing colon. */
    public static Map<String, String> prefixesOf(Map<String, String> declared) {
        Map<String, String> result = new TreeMap<>();
        declared.forEach((name, namespace) -> result.put(name.endsWith(":")
                ? name.substring(0, name.length() - 1) : name, namespace));
        result.putIfAbsent("owl", "http://www.w3.org/2002/07/owl#");
        result.putIfAbsent("rdf", "http://www.w3.org/1999/02/22-rdf-syntax-ns#");
        result.putIfAbsent("rdfs", "http://www.w3.org/2000/01/rdf-schema#");
        result.putIfAbsent("xsd", "http://www.w3.org/2001/XMLSchema#");
        return result;
    }
}
