// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
package io.github.armor.core.answers;

import io.github.armor.core.api.ArmorException;
import io.github.armor.core.api.ExitCode;
import io.github.armor.core.reference.OntologyFiles;
import io.github.armor.core.reference.Reference;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import org.semanticweb.owlapi.apibinding.OWLManager;
import org.semanticweb.owlapi.expression.OWLEntityChecker;
import org.semanticweb.owlapi.functional.parser.OWLFunctionalSyntaxOWLParserFactory;
import org.semanticweb.owlapi.io.OWLParserException;
import org.semanticweb.owlapi.io.StringDocumentSource;
import org.semanticweb.owlapi.manchestersyntax.parser.ManchesterOWLSyntax;
import org.semanticweb.owlapi.manchestersyntax.renderer.ManchesterOWLSyntaxOWLObjectRendererImpl;
import org.semanticweb.owlapi.model.EntityType;
import org.semanticweb.owlapi.model.IRI;
import org.semanticweb.owlapi.model.OWLAnnotationProperty;
import org.semanticweb.owlapi.model.OWLAxiom;
import org.semanticweb.owlapi.model.OWLClass;
import org.semanticweb.owlapi.model.OWLClassExpression;
import org.semanticweb.owlapi.model.OWLDataFactory;
import org.semanticweb.owlapi.model.OWLDataProperty;
import org.semanticweb.owlapi.model.OWLDatatype;
import org.semanticweb.owlapi.model.OWLEntity;
import org.semanticweb.owlapi.model.OWLNamedIndividual;
import org.semanticweb.owlapi.model.OWLObject;
import org.semanticweb.owlapi.model.OWLObjectProperty;
import org.semanticweb.owlapi.model.OWLOntology;
import org.semanticweb.owlapi.model.OWLOntologyCreationException;
import org.semanticweb.owlapi.model.OWLOntologyManager;
import org.semanticweb.owlapi.model.OWLRuntimeException;
import org.semanticweb.owlapi.model.SWRLRule;
import org.semanticweb.owlapi.model.parameters.Imports;
import org.semanticweb.owlapi.util.OntologyAxiomPair;
import org.semanticweb.owlapi.util.SimpleShortFormProvider;
import org.semanticweb.owlapi.util.mansyntax.ManchesterOWLSyntaxParser;
import org.semanticweb.owlapi.vocab.OWL2Datatype;
import org.semanticweb.owlapi.vocab.SWRLBuiltInsVocabulary;

/**
 * Class expressions, axioms and SWRL rules written by clients, parsed with the OWL API's own
 * Manchester and functional-syntax parsers; names follow the same rules as plain arguments.
 */
public final class Syntax {
    private static final Pattern NEW_CLASS_NAME = Pattern.compile("[\\p{L}_][\\p{L}\\p{N}_.\\-]*");
    // Protégé writes built-ins as swrlb:lessThan; the OWL API parser knows them by bare name or full IRI.
    private static final Pattern SWRLB_PREFIXED = Pattern.compile("\\bswrlb:([A-Za-z]+)\\s*\\(");
    private static final int EXPECTED_TOKENS_SHOWN = 12;
    // Starts only where a name starts and never gives characters back: linear even on a
    // 100,000-character argument (a free start backtracked quadratically).
    private static final Pattern BINARY_ATOM = Pattern.compile(
            "(?<![\\p{L}\\p{N}_.\\-])([\\p{L}_][\\p{L}\\p{N}_.\\-]*+)\\s*+\\(\\s*+\\?[^,()]++,");
    // SWRL's own atoms, never entity names.
    private static final Set<String> SWRL_KEYWORDS = Set.of("DifferentFrom", "SameAs", "differentFrom", "sameAs");
    private static final String SWRL_BUILT_INS = "http://www.w3.org/2003/11/swrlb#";
    // The OWL API parser reads a missing operand ("isIn some", "not") as owl:Thing instead of
    // failing; an operator with nothing after it is refused here, before parsing.
    private static final Pattern DANGLING_OPERATOR = Pattern.compile(
            "(?i)\\b(not|some|only|value|and|or|that|inverse|(?:min|max|exactly)(?:\\s+\\d+)?)\\s*(?=$|[)\\],])");
    // Quoted literals first (skipped whole), IRIs, then names with an optional prefix.
    private static final Pattern EXPRESSION_WORD = Pattern.compile(
            "\"(?:[^\"\\\\]|\\\\.)*+\"|<[^>\\s]*+>|[\\p{L}_][\\p{L}\\p{N}_.\\-]*+(?::[\\p{L}\\p{N}_.\\-]++)?");
    private static final Pattern RESTRICTION_NEXT = Pattern.compile("\\s*+(?:some|only|value|min|max|exactly|Self)\\b");
    private static final Pattern VALUE_BEFORE = Pattern.compile("\\bvalue$");
    private static final Set<String> LITERAL_WORDS = Set.of("true", "false");
    private static final int UNKNOWN_WORDS_SHOWN = 5;
    private static final Pattern FUNCTIONAL_POSITION = Pattern.compile("line (\\d+), column (\\d+)");
    private static final Pattern FUNCTIONAL_AXIOM = Pattern.compile("^\\s*[A-Z][A-Za-z]*\\s*\\(.*", Pattern.DOTALL);

    private Syntax() {}

    public static OWLClassExpression classExpression(Reference reference, String text) {
        ManchesterOWLSyntaxParser parser = parser(reference, text);
        try {
            return parser.parseClassExpression();
        } catch (OWLParserException e) {
            // A misspelt property reads as a new class, so the parser stumbles on the word after it
            // ("Encountered some"): the unknown words are what the client needs to hear first.
            String unknown = unknownWords(reference, text);
            throw new ArmorException(ExitCode.BAD_SYNTAX, "cannot parse '" + abbreviated(text) + "': "
                    + (unknown.isEmpty() ? "" : "the reference does not know " + unknown + "; ") + shortened(e), e);
        }
    }

    /** The words of a class expression that name no entity of the reference, each with the known names closest to it. */
    private static String unknownWords(Reference reference, String text) {
        ReferenceEntityChecker checker = new ReferenceEntityChecker(reference, Set.of());
        List<String> described = new java.util.ArrayList<>();
        java.util.regex.Matcher word = EXPRESSION_WORD.matcher(text);
        while (word.find() && described.size() < UNKNOWN_WORDS_SHOWN) {
            String name = word.group();
            if (name.startsWith("\"") || ManchesterOWLSyntax.parse(name) != null || LITERAL_WORDS.contains(name)
                    || checker.knows(name)) {
                continue;
            }
            String before = text.substring(0, word.start()).stripTrailing();
            EntityType<?> type = RESTRICTION_NEXT.matcher(text).region(word.end(), text.length()).lookingAt()
                    ? EntityType.OBJECT_PROPERTY
                    : before.endsWith("{") || before.endsWith(",") || VALUE_BEFORE.matcher(before).find()
                    ? EntityType.NAMED_INDIVIDUAL : EntityType.CLASS;
            String description = reference.names().describeUnknown(type, name);
            if (type == EntityType.OBJECT_PROPERTY && !description.contains("did you mean")) {
                String asData = reference.names().describeUnknown(EntityType.DATA_PROPERTY, name);
                description = asData.contains("did you mean") ? asData : description;
            }
            if (!described.contains(description)) {
                described.add(description);
            }
        }
        return String.join(", ", described);
    }

    /** One axiom in Manchester syntax ({@code Robot SubClassOf isIn exactly 1 Location}) or functional syntax. */
    public static OWLAxiom axiom(Reference reference, String text) {
        if (FUNCTIONAL_AXIOM.matcher(text).matches()) {
            return functionalAxiom(reference, text);
        }
        ManchesterOWLSyntaxParser parser = parser(reference, text);
        return parse(text, parser::parseAxiom);
    }

    /**
     * A SWRL rule ({@code Robot(?r), isIn(?r, ?l) -> Occupied(?l)}), labelled with its name. A
     * predicate the ontology lacks is created: a class when it takes one argument, an object
     * property when it takes two.
     */
    public static SWRLRule rule(Reference reference, String name, String text) {
        String normalised = SWRLB_PREFIXED.matcher(text).replaceAll("$1(");
        Set<String> newProperties = new java.util.HashSet<>();
        java.util.regex.Matcher binary = BINARY_ATOM.matcher(normalised);
        while (binary.find()) {
            String predicate = binary.group(1);
            if (!SWRL_KEYWORDS.contains(predicate)
                    && SWRLBuiltInsVocabulary.getBuiltIn(IRI.create(SWRL_BUILT_INS + predicate)) == null) {
                newProperties.add(predicate);
            }
        }
        ManchesterOWLSyntaxParser parser = OWLManager.createManchesterParser();
        parser.setDefaultOntology(reference.ontology());
        parser.setOWLEntityChecker(new ReferenceEntityChecker(reference, newProperties));
        tokenize(parser, "Rule: " + normalised, text);
        List<OntologyAxiomPair> parsed = parse(text, parser::parseRuleFrame);
        if (parsed.size() != 1 || !(parsed.get(0).getAxiom() instanceof SWRLRule rule)) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "expected exactly one SWRL rule in '" + abbreviated(text) + "'");
        }
        OWLDataFactory factory = reference.factory();
        return factory.getSWRLRule(rule.body().toList(), rule.head().toList(),
                Set.of(factory.getRDFSLabel(factory.getOWLLiteral(name))));
    }

    public static String render(Reference reference, boolean fullIri, OWLObject object) {
        ManchesterOWLSyntaxOWLObjectRendererImpl renderer = new ManchesterOWLSyntaxOWLObjectRendererImpl();
        SimpleShortFormProvider shortForms = new SimpleShortFormProvider();
        renderer.setShortFormProvider(entity -> fullIri ? "<" + entity.getIRI() + ">" : shortForms.getShortForm(entity));
        return renderer.render(object).replaceAll("\\s+", " ").trim();
    }

    private static ManchesterOWLSyntaxParser parser(Reference reference, String text) {
        java.util.regex.Matcher dangling = DANGLING_OPERATOR.matcher(text);
        if (dangling.find()) {
            String before = text.substring(0, dangling.end());
            int line = (int) before.chars().filter(c -> c == '\n').count() + 1;
            int column = dangling.end() - before.lastIndexOf('\n');
            throw new ArmorException(ExitCode.BAD_SYNTAX, "cannot parse '" + abbreviated(text) + "': no operand after '"
                    + dangling.group(1) + "' at line " + line + " column " + column + ". Expected one of: Class name"
                    + " Object property name Data property name ( {");
        }
        ManchesterOWLSyntaxParser parser = OWLManager.createManchesterParser();
        parser.setDefaultOntology(reference.ontology());
        parser.setOWLEntityChecker(new ReferenceEntityChecker(reference, Set.of()));
        tokenize(parser, text, text);
        return parser;
    }

    /** The OWL API's tokenizer reads past the end of a text whose last character is an escape. */
    private static void tokenize(ManchesterOWLSyntaxParser parser, String text, String clientText) {
        try {
            parser.setStringToParse(text);
        } catch (IndexOutOfBoundsException e) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "cannot parse '" + abbreviated(clientText) + "': "
                    + (clientText.endsWith("\\") ? "it ends in an escape character '\\' with nothing to escape"
                    : "the text ends inside an escape sequence"), e);
        }
    }

    private static <T> T parse(String text, java.util.function.Supplier<T> parse) {
        try {
            return parse.get();
        } catch (OWLParserException e) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "cannot parse '" + abbreviated(text) + "': " + shortened(e), e);
        } catch (OWLRuntimeException e) {
            // The data factory refuses some parsed axioms outright (DisjointClasses of owl:Thing alone).
            throw new ArmorException(ExitCode.BAD_SYNTAX, "not an OWL 2 axiom: '" + abbreviated(text) + "': "
                    + e.getMessage(), e);
        }
    }

    /** The functional parser's complaint with its position in the client's text, not in the wrapper. */
    private static String functionalError(OWLOntologyCreationException e, int linesBefore, String text) {
        String message = String.valueOf(e.getMessage());
        String complaint = message.lines().filter(l -> l.contains("Encountered") || l.contains("Lexical error"))
                .findFirst().orElse(message.lines().findFirst().orElse("")).trim();
        complaint = FUNCTIONAL_POSITION.matcher(complaint).replaceAll("").trim();
        java.util.regex.Matcher position = FUNCTIONAL_POSITION.matcher(message);
        if (position.find()) {
            int line = Integer.parseInt(position.group(1)) - linesBefore;
            List<String> lines = text.lines().toList();
            if (line >= 1 && line <= lines.size()) {
                complaint += " at line " + line + " column " + position.group(2);
            } else {
                complaint = "unexpected end of the axiom at line " + Math.max(1, lines.size()) + " column "
                        + (lines.isEmpty() ? 1 : lines.get(lines.size() - 1).length() + 1);
            }
        }
        return complaint.length() > 300 ? complaint.substring(0, 300) + " ..." : complaint;
    }

    /** Client text quoted in an error, cut so that a huge argument does not make a huge answer. */
    private static String abbreviated(String text) {
        return text.length() <= 200 ? text : text.substring(0, 200) + "... (" + text.length() + " characters)";
    }

    /** The parser's position and the first expected tokens; its full list can name hundreds of built-ins. */
    private static String shortened(OWLParserException e) {
        String message = e.getMessage().replaceAll("\\s+", " ").trim();
        int expected = message.indexOf("Expected one of:");
        if (expected < 0) {
            return message;
        }
        List<String> tokens = List.of(message.substring(expected + "Expected one of:".length()).trim().split(" "));
        String shown = String.join(" ", tokens.stream().filter(t -> !t.startsWith("<" + SWRL_BUILT_INS))
                .limit(EXPECTED_TOKENS_SHOWN).toList());
        return message.substring(0, expected) + "Expected one of: " + shown
                + (tokens.size() > EXPECTED_TOKENS_SHOWN ? " ..." : "");
    }

    private static OWLAxiom functionalAxiom(Reference reference, String text) {
        StringBuilder document = new StringBuilder();
        reference.names().prefixes().forEach((name, namespace) ->
                document.append("Prefix(").append(name).append(":=<").append(namespace).append(">)\n"));
        document.append("Prefix(:=<").append(reference.names().defaultNamespace()).append(">)\n");
        document.append("Ontology(\n");
        int linesBefore = (int) document.chars().filter(c -> c == '\n').count();
        document.append(text).append("\n)\n");
        OWLOntology parsed;
        try {
            OWLOntologyManager manager = OntologyFiles.inlineManager();
            manager.setOntologyParsers(Set.of(new OWLFunctionalSyntaxOWLParserFactory()));
            parsed = manager.loadOntologyFromOntologyDocument(new StringDocumentSource(document.toString(),
                    "urn:armor:axiom", new org.semanticweb.owlapi.formats.FunctionalSyntaxDocumentFormat(), null));
        } catch (OWLOntologyCreationException e) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "cannot parse functional-syntax axiom '" + abbreviated(text) + "': "
                    + functionalError(e, linesBefore, text), e);
        }
        if (parsed.importsDeclarations().findAny().isPresent()) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "'" + abbreviated(text) + "' holds an Import, which is not an"
                    + " axiom; LOAD the ontology that imports it instead");
        }
        List<OWLAxiom> axioms = parsed.axioms().filter(a -> !a.isOfType(org.semanticweb.owlapi.model.AxiomType.DECLARATION))
                .toList();
        if (axioms.size() != 1) {
            throw new ArmorException(ExitCode.BAD_SYNTAX, "expected exactly one axiom in '" + abbreviated(text) + "', found "
                    + axioms.size());
        }
        return axioms.get(0);
    }

    /**
     * Lets the Manchester parser see the reference's entities by the argument naming rules. A
     * name that is no entity at all is taken as a new class (contract: naming creates); other
     * kinds must exist, so that the parser can tell a property from a class.
     */
    private static final class ReferenceEntityChecker implements OWLEntityChecker {
        private final Reference reference;
        private final OWLOntology ontology;
        private final OWLDataFactory factory;
        private final Set<String> newObjectProperties;

        ReferenceEntityChecker(Reference reference, Set<String> newObjectProperties) {
            this.reference = reference;
            this.newObjectProperties = newObjectProperties;
            this.ontology = reference.ontology();
            this.factory = reference.factory();
        }

        @Override
        public OWLClass getOWLClass(String name) {
            OWLClass existing = existing(EntityType.CLASS, name);
            if (existing != null || isAnyEntity(name) || !NEW_CLASS_NAME.matcher(name).matches()
                    || ManchesterOWLSyntax.parse(name) != null || SWRL_KEYWORDS.contains(name)
                    || newObjectProperties.contains(name)
                    || SWRLBuiltInsVocabulary.getBuiltIn(IRI.create(SWRL_BUILT_INS + name)) != null) {
                return existing;
            }
            IRI iri = iriOrNull(EntityType.CLASS, name);
            return iri == null ? null : factory.getOWLClass(iri);
        }

        @Override
        public OWLObjectProperty getOWLObjectProperty(String name) {
            OWLObjectProperty existing = existing(EntityType.OBJECT_PROPERTY, name);
            if (existing != null || !newObjectProperties.contains(name) || isAnyEntity(name)
                    || existing(EntityType.CLASS, name) != null) {
                return existing;
            }
            IRI iri = iriOrNull(EntityType.OBJECT_PROPERTY, name);
            return iri == null ? null : factory.getOWLObjectProperty(iri);
        }

        @Override
        public OWLDataProperty getOWLDataProperty(String name) {
            return existing(EntityType.DATA_PROPERTY, name);
        }

        @Override
        public OWLNamedIndividual getOWLIndividual(String name) {
            return existing(EntityType.NAMED_INDIVIDUAL, name);
        }

        @Override
        public OWLDatatype getOWLDatatype(String name) {
            IRI iri = iriOrNull(EntityType.DATATYPE, name);
            if (iri == null) {
                IRI xsd = IRI.create("http://www.w3.org/2001/XMLSchema#" + name);
                return OWL2Datatype.isBuiltIn(xsd) ? factory.getOWLDatatype(xsd) : null;
            }
            return OWL2Datatype.isBuiltIn(iri) || ontology.containsDatatypeInSignature(iri, Imports.INCLUDED)
                    ? factory.getOWLDatatype(iri) : null;
        }

        @Override
        public OWLAnnotationProperty getOWLAnnotationProperty(String name) {
            return existing(EntityType.ANNOTATION_PROPERTY, name);
        }

        private <E extends OWLEntity> E existing(EntityType<E> type, String name) {
            IRI iri = iriOrNull(type, name);
            if (iri == null) {
                return null;
            }
            E entity = factory.getOWLEntity(type, iri);
            return ontology.containsEntityInSignature(entity, Imports.INCLUDED) || entity.isBuiltIn() ? entity : null;
        }

        /** Whether a word names an entity of the reference or a datatype (a new class does not count). */
        boolean knows(String name) {
            return existing(EntityType.CLASS, name) != null || isAnyEntity(name) || getOWLDatatype(name) != null;
        }

        private boolean isAnyEntity(String name) {
            return existing(EntityType.OBJECT_PROPERTY, name) != null || existing(EntityType.DATA_PROPERTY, name) != null
                    || existing(EntityType.NAMED_INDIVIDUAL, name) != null
                    || existing(EntityType.ANNOTATION_PROPERTY, name) != null
                    || existing(EntityType.DATATYPE, name) != null;
        }

        private IRI iriOrNull(EntityType<?> type, String name) {
            try {
                return reference.names().iri(type, name);
            } catch (ArmorException e) {
                if (e.exitCode() == ExitCode.AMBIGUOUS_NAME) {
                    throw e;
                }
                return null;
            }
        }
    }
}
