// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
// The ARMOR web view: shows what the node's server answers (armor_service/web/server.py) and
// refetches what is on screen when the node's WebSocket says a reference changed. It computes
// nothing about ontologies: every class, type and link comes from the knowledge core.
'use strict';

const TABS = ['graph', 'classes', 'individuals', 'query', 'recent'];
const PAGE_SIZE = 50;
const PALETTE = ['#4e79a7', '#f28e2b', '#59a14f', '#e15759', '#76b7b2', '#edc948', '#b07aa1',
  '#ff9da7', '#9c755f', '#2f6690', '#c0392b', '#17becf'];
// Above this many nodes even the layout worker would take minutes: a grid instead.
const FORCE_LAYOUT_MAX_NODES = 2000;

const state = {
  overview: [],
  selected: null,
  tab: 'graph',
  revisions: null,
  answered: {},        // directives the node answered, by reference (the recent list follows them)
  classIri: null,
  individualIri: null,
  individualSearch: '',
  individualOffset: 0,
  openClasses: new Set(),
  closedClasses: new Set(),
  graphChoice: null,   // {properties: [iri] | null for all, class, focus, limit}
  properties: [],      // the selected reference's object properties
  classIndex: new Map(),  // its classes' places in their list sorted by name (colourOf)
  fetchedAt: 0,
};

// ---------------------------------------------------------------- small helpers
function el(tag, attributes, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes || {})) {
    if (value === null || value === undefined || value === false) continue;
    if (name === 'className') node.className = value;
    else if (name === 'text') node.textContent = value;
    else node.setAttribute(name, value === true ? '' : String(value));
  }
  for (const child of children.flat(Infinity)) {
    if (child === null || child === undefined) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

const $ = (selector) => document.querySelector(selector);

/** Replaces a container's children, leaving out the null ones (parts shown only sometimes). */
function fill(container, ...children) {
  container.replaceChildren(...children.flat(Infinity).filter((child) => child !== null && child !== undefined));
}

async function api(path, options) {
  const response = await fetch(path, options);
  let body = null;
  try {
    body = await response.json();
  } catch (ignored) {
    body = null;
  }
  if (!response.ok) {
    const error = body && body.error;
    const failure = new Error(error ? `${error.description} (exit code ${error.exit_code})`
      : `${response.status} ${response.statusText}`);
    failure.status = response.status;
    throw failure;
  }
  return body;
}

function postJson(path, payload) {
  return api(path, {method: 'POST', headers: {'Content-Type': 'application/json'},
    body: JSON.stringify(payload)});
}

function referencePath(suffix) {
  return `/api/references/${encodeURIComponent(state.selected)}${suffix || ''}`;
}

/** A short name for an entity as directives answer it: <http://x#Room> or Room -> Room. */
function shortName(text) {
  const bare = text.startsWith('<') && text.endsWith('>') ? text.slice(1, -1) : text;
  const cut = Math.max(bare.lastIndexOf('#'), bare.lastIndexOf('/'));
  return cut >= 0 && cut < bare.length - 1 ? bare.slice(cut + 1) : bare;
}

function clock(ms) {
  const at = new Date(ms);
  return at.toLocaleTimeString([], {hour12: false}) + '.' + String(at.getMilliseconds()).padStart(3, '0');
}

/**
 * A type's colour: from the class's place among the reference's classes sorted by name, not
 * from what happens to be on screen, so that it is the same on every page, in every state of
 * the individuals and in the README's picture. The first classes take the palette's colours,
 * all different; beyond it, hues a golden angle apart. A label of several types takes the
 * first one's; no class (owl:Thing) is grey.
 */
function colourOf(types) {
  const index = state.classIndex.get(types.split(', ')[0]);
  if (index === undefined) return '#98a2b3';
  if (index < PALETTE.length) return PALETTE[index];
  return `hsl(${Math.round((index * 137.508) % 360)}, 55%, ${[45, 32, 60][index % 3]}%)`;
}

/** The reference's classes by name, sorted: the colours of the graph's types (colourOf). */
async function loadClassIndex(shown) {
  const hierarchy = await api(referencePath('/classes'));
  const names = [...new Set(hierarchy.classes.map((owlClass) => owlClass.name))].sort();
  // A type the hierarchy leaves out gets a place after them, and is not asked for again.
  names.push(...[...shown].filter((name) => !names.includes(name)).sort());
  state.classIndex = new Map(names.map((name, index) => [name, index]));
}

/** Axioms as the core writes them, with <full IRIs> shortened to their names for reading. */
function readable(text) {
  return text.replace(/<[^<>]*[#/]([^<>#/]+)>/g, '$1');
}

/** An entity as a link: kind 'class' or 'individual'; marked asserted or inferred when known. */
function entityLink(entity, kind) {
  const marked = entity.asserted === undefined ? '' : entity.asserted ? 'asserted' : 'inferred';
  return el('a', {className: `entity ${marked}`, 'data-kind': kind, 'data-iri': entity.iri,
    title: marked ? `${entity.iri} (${marked === 'asserted' ? 'asserted' : 'inferred by the reasoner'})`
      : entity.iri, text: entity.name});
}

/** Entities as links; with {@code why}, each inferred one gets the "why?" it makes. */
function entityList(entities, kind, why) {
  if (!entities.length) return el('span', {className: 'muted', text: 'none'});
  return el('span', {className: 'entity-list'}, entities.map((e) => el('span', {}, entityLink(e, kind),
    why && e.asserted === false ? why(e) : null)));
}

// ---------------------------------------------------------------- why? (EXPLAIN, docs/explanations.md)
/** A "why?" button for an inferred fact: kind instance, objectprop or subclass, and its arguments (IRIs). */
function whyButton(kind, args) {
  return el('button', {className: 'why', type: 'button', 'data-why': kind, 'data-args': JSON.stringify(args),
    title: 'why does the reasoner infer this? (its justifications)', text: 'why?'});
}

/**
 * An axiom's text with each <IRI> a link to its page: a class when the hierarchy has it or its
 * name starts with a capital (the OWL convention, for a tree not loaded yet), else an individual.
 */
function axiomNodes(text) {
  const nodes = [];
  let last = 0;
  for (const match of text.matchAll(/<([^<>\s]+)>/g)) {
    nodes.push(text.slice(last, match.index));
    const iri = match[1];
    const kind = classByIri.has(iri) || /^[A-Z]/.test(shortName(iri)) ? 'class' : 'individual';
    nodes.push(el('a', {className: 'entity', 'data-kind': kind, 'data-iri': iri, href: '#', title: iri,
      text: shortName(iri)}));
    last = match.index + match[0].length;
  }
  nodes.push(text.slice(last));
  return nodes;
}

/** Shows the justifications of the button's fact in a box after it (a second click hides them). */
async function showWhy(button) {
  const next = button.nextElementSibling;
  if (next && next.classList.contains('why-box')) {
    next.remove();
    return;
  }
  const box = el('div', {className: 'why-box'});
  button.after(box);
  fill(box, el('p', {className: 'muted', text: 'explaining…'}));
  const params = new URLSearchParams({kind: button.dataset.why});
  for (const arg of JSON.parse(button.dataset.args)) params.append('arg', arg);
  try {
    const answer = await api(referencePath('/explain?' + params));
    if (!answer.justifications.length) {
      fill(box, directiveFailure(answer));
      return;
    }
    fill(box, answer.justifications.map((justification, index) => el('div', {className: 'justification'},
      el('p', {className: 'muted', text: `justification ${index + 1}`}),
      el('ul', {}, justification.map((axiom) => el('li', {className: `axiom ${axiom.kind}`},
        el('span', {className: 'tag', text: axiom.kind}), ' ', axiom.kind === 'rule' ? `${axiom.rule}: ` : '',
        axiomNodes(axiom.text), Object.keys(axiom.bindings).length ? [' (', Object.entries(axiom.bindings)
          .map(([variable, value], i) => [i ? ', ' : '', `${variable}=`, axiomNodes(value)]), ')'] : null))))),
      answer.timeout ? el('p', {className: 'error', text: answer.description}) : null,
      el('p', {className: 'why-sentence', text: answer.sentence}));
  } catch (error) {
    showError(box, error);
  }
}

function showError(container, error) {
  container.replaceChildren(el('p', {className: 'error', text: String(error.message || error)}));
}

/**
 * Runs a refresh at most once at a time: asked again meanwhile, it runs once more afterwards.
 * However fast the changes come, a page never queues up fetches, and never misses the last one.
 */
class Refresher {
  constructor(task) {
    this.task = task;
    this.running = false;
    this.again = false;
  }

  request() {
    if (this.running) {
      this.again = true;
      return;
    }
    this.run();
  }

  async run() {
    this.running = true;
    try {
      do {
        this.again = false;
        try {
          await this.task();
        } catch (error) {
          console.warn('refresh failed', error);
        }
      } while (this.again);
    } finally {
      this.running = false;
    }
  }
}

// ---------------------------------------------------------------- overview and summary
const overviewRefresher = new Refresher(async () => {
  const overview = await api('/api/overview');
  state.overview = overview.references;
  state.fetchedAt = performance.now();
  renderStateDamage(overview.state_damage || []);
  renderReferenceList();
  if (!state.selected && state.overview.length) {
    const wanted = decodeURIComponent(location.hash.slice(2).split('/')[0] || '');
    select(state.overview.some((r) => r.name === wanted) ? wanted : state.overview[0].name, null);
  } else if (state.selected && !state.overview.some((r) => r.name === state.selected)) {
    const gone = $('#gone');
    gone.textContent = `Reference "${state.selected}" is no longer loaded (it was dropped). `
      + (state.overview.length ? 'Choose another on the left.' : '');
    gone.hidden = false;
    state.selected = null;
    $('#reference').hidden = true;
  }
  renderSummary();
});

// What GET STATE DAMAGE answers: restores that lost something, references refusing changes.
function renderStateDamage(damage) {
  const banner = $('#state-damage');
  banner.hidden = !damage.length;
  fill($('#state-damage-list'), ...damage.map((d) => el('li', {text: d.refusing_changes
    ? `"${d.reference}": changes refused since ${d.since} (not durable: ${d.refusing_changes})`
    : `"${d.reference}" ${d.restored ? `restored up to revision ${d.revision}` : 'NOT restored'}`
      + ` (${d.when}): ${(d.problems || []).join('; ')}. Set aside in ${d.kept_in}`})));
}

function summaryOf(name) {
  return state.overview.find((r) => r.name === name);
}

function leaseText(summary) {
  if (summary.lease_left_s === undefined) return '';
  const elapsed = (performance.now() - state.fetchedAt) / 1000;
  return ` (lease ${Math.max(0, Math.round(summary.lease_left_s - elapsed))} s left)`;
}

function renderReferenceList() {
  const list = $('#reference-list');
  if (!state.overview.length) {
    fill(list, el('p', {className: 'muted', text: 'No reference is loaded.'}));
    return;
  }
  fill(list, ...state.overview.map((r) => {
    const badge = r.consistent ? el('span', {className: 'badge ok', text: 'consistent'})
      : el('span', {className: 'badge bad', text: 'INCONSISTENT'});
    const rows = [
      ['reasoner', r.reasoner],
      ['reasoning', r.reasoning],
      ['profile', r.profile],
      ['classes', r.busy ? '…' : (r.classification || r.classes)],
      ['individuals', r.busy ? '…' : r.individuals],
      ['axioms', r.busy ? '…' : r.axioms],
    ];
    if (r.mounted_by) rows.push(['mounted by', r.mounted_by + leaseText(r)]);
    if (r.last_reasoning_at_ms) {
      rows.push(['reasoned', `${clock(r.last_reasoning_at_ms)} in ${r.last_reasoning_ms.toFixed(1)} ms`]);
    }
    return el('div', {className: `card${r.name === state.selected ? ' selected' : ''}`, 'data-name': r.name,
      role: 'button', tabindex: 0},
    el('div', {className: 'name'}, r.name, badge, r.busy ? el('span', {className: 'badge busy', text: 'busy'}) : null),
    el('dl', {}, rows.map(([k, v]) => [el('dt', {text: k}), el('dd', {text: String(v)})])));
  }));
}

function renderSummary() {
  const summary = summaryOf(state.selected);
  if (!summary) return;
  const mode = (buffered) => buffered ? 'buffered' : 'immediate';
  const parts = [
    `${summary.reasoner} reasoner`,
    `manipulation ${mode(summary.buffered_manipulation)}`,
    `reasoner ${mode(summary.buffered_reasoner)}`,
    `reasoning ${summary.reasoning}`,
    summary.mounted_by ? `mounted by ${summary.mounted_by}${leaseText(summary)}` : 'not mounted',
  ];
  if (!summary.busy) {
    parts.push(`profile ${summary.profile}`, summary.classification || `${summary.classes} classes`,
      `${summary.individuals} individuals`,
      `${summary.axioms} axioms (${summary.logical_axioms} logical)`);
    if (summary.pending_changes) parts.push('changes waiting for APPLY');
  } else {
    parts.push('busy: another directive holds it');
  }
  if (summary.last_reasoning_at_ms) {
    parts.push(`last reasoning ${clock(summary.last_reasoning_at_ms)}, ${summary.last_reasoning_ms.toFixed(1)} ms`);
  }
  fill($('#summary'), el('strong', {text: summary.name}), parts.join(' · '));
  const banner = $('#inconsistency');
  if (!summary.consistent && banner.hidden) {
    fill($('#explanation'), el('li', {className: 'muted', text: 'asking the reasoner…'}));
    consistencyRefresher.request();
  }
  banner.hidden = summary.consistent;
}

const consistencyRefresher = new Refresher(async () => {
  const list = $('#explanation');
  try {
    const answer = await api(referencePath('/consistency'));
    fill(list, ...(answer.explanation.length ? answer.explanation.map((axiom) => el('li', {title: axiom,
      text: readable(axiom)}))
      : [el('li', {text: answer.success ? 'no explanation found' : answer.description})]));
  } catch (error) {
    fill(list, el('li', {className: 'error', text: String(error.message)}));
  }
});

// ---------------------------------------------------------------- selection and tabs
function select(name, tab) {
  const changed = name !== state.selected;
  state.selected = name;
  if (tab) state.tab = tab;
  if (changed) {
    state.classIri = null;
    state.individualIri = null;
    state.individualOffset = 0;
    state.individualSearch = '';
    $('#individual-search').value = '';
    state.openClasses = new Set();
    state.closedClasses = new Set();
    state.graphChoice = null;
    state.properties = [];
    state.classIndex = new Map();
    fill($('#class-detail'), el('p', {className: 'muted', text: 'Choose a class.'}));
    fill($('#individual-detail'), el('p', {className: 'muted', text: 'Choose an individual.'}));
    $('#inconsistency').hidden = true;
  }
  const hash = `#/${encodeURIComponent(name)}/${state.tab}`;
  if (location.hash !== hash) history.replaceState(null, '', hash);
  $('#reference').hidden = false;
  $('#gone').hidden = true;
  for (const button of document.querySelectorAll('.tabs button')) {
    button.setAttribute('aria-selected', String(button.dataset.tab === state.tab));
  }
  for (const tabName of TABS) $(`#tab-${tabName}`).hidden = tabName !== state.tab;
  renderReferenceList();
  renderSummary();
  refreshSelected();
}

function refreshSelected() {
  if (!state.selected) return;
  tabRefreshers[state.tab].request();
  if (state.tab === 'classes' && state.classIri) classDetailRefresher.request();
  if (state.tab === 'individuals' && state.individualIri) individualDetailRefresher.request();
}

// ---------------------------------------------------------------- graph
let graph = null;
let layoutSettled = true;
let layoutAsked = 0;
// The force-directed layout runs in a worker (layout-worker.js): the page never waits for it.
const layoutWorker = new Worker('/static/layout-worker.js');
layoutWorker.onmessage = (event) => {
  if (event.data.id !== layoutAsked || graph === null) return;  // a newer layout is on its way
  graph.batch(() => {
    for (const [id, position] of event.data.positions) {
      const node = graph.getElementById(id);
      if (node.nonempty()) node.position(position);
    }
  });
  graph.fit(undefined, 30);
  layoutSettled = true;
};

// Labels' size on screen, in pixels, whatever the zoom down to LABEL_MIN_ZOOM (below it they
// shrink with the graph, and vanish under min-zoomed-font-size, rather than hide it).
const LABEL_PX = {node: 14, edge: 12};
const LABEL_MIN_ZOOM = 0.4;
let labelFrame = 0;

function keepLabelsReadable() {
  if (labelFrame) return;
  labelFrame = requestAnimationFrame(() => {
    labelFrame = 0;
    const scale = 1 / Math.max(graph.zoom(), LABEL_MIN_ZOOM);
    graph.style()
      .selector('node').style({'font-size': LABEL_PX.node * scale, 'text-margin-y': 4 * scale})
      .selector('edge').style({'font-size': LABEL_PX.edge * scale, 'text-background-padding': 2 * scale})
      .update();
  });
}

/** Lays the graph out again, from where its nodes are unless `randomize`. */
function layOut(randomize) {
  const count = graph.nodes().length;
  layoutAsked += 1;
  if (count > FORCE_LAYOUT_MAX_NODES) {
    graph.layout({name: 'grid', fit: true, avoidOverlap: true}).run();
    layoutSettled = true;
    return;
  }
  layoutSettled = false;
  const elements = graph.elements().map((e) => e.isNode()
    ? {group: 'nodes', data: {id: e.id()}, position: {...e.position()}}
    : {group: 'edges', data: {id: e.id(), source: e.data('source'), target: e.data('target')}});
  // Fewer iterations as the graph grows: a large sample settles in seconds, not minutes.
  layoutWorker.postMessage({id: layoutAsked, elements, randomize,
    numIter: count <= 100 ? 3000 : count <= 400 ? 1500 : 600});
}

function graphChoice() {
  if (!state.graphChoice) state.graphChoice = {properties: null, class: '', focus: '', limit: 300};
  return state.graphChoice;
}

async function loadProperties() {
  const reference = await api(referencePath());
  state.properties = reference.object_properties;
  const choice = graphChoice();
  const box = $('#graph-properties');
  fill(box, el('legend', {text: 'Links'}), ...state.properties.map((p) => el('label', {},
    el('input', {type: 'checkbox', name: 'property', value: p.iri,
      checked: choice.properties === null || choice.properties.includes(p.iri)}), ' ', p.name)));
}

const graphRefresher = new Refresher(async () => {
  const name = state.selected;
  if (!state.properties.length) await loadProperties();
  const choice = graphChoice();
  const query = new URLSearchParams();
  const properties = choice.properties === null ? state.properties.map((x) => x.iri) : choice.properties;
  for (const p of properties) query.append('property', p);
  if (!properties.length) query.append('property', '');  // none ticked: links by no property
  if (choice.class) query.set('class', choice.class);
  if (choice.focus) query.set('focus', choice.focus);
  query.set('limit', choice.limit);
  let data;
  try {
    data = await api(referencePath('/graph?' + query));
  } catch (error) {
    fill($('#graph-note'), el('span', {className: 'error', text: error.message}));
    return;
  }
  if (name !== state.selected) return;
  const shown = new Set(data.nodes.filter((node) => node.types.length).map((node) => node.types[0].name));
  if ([...shown].some((type) => !state.classIndex.has(type))) {
    try {
      await loadClassIndex(shown);  // first time, or a class new to the schema
    } catch (error) {
      // grey nodes until the next refresh: the graph itself is fine
    }
    if (name !== state.selected) return;
  }
  renderGraph(data);
});

function renderGraph(data) {
  const note = $('#graph-note');
  const shown = `${data.nodes.length} individuals, ${data.edges.length} links`;
  note.textContent = data.truncated
    ? `${shown}: a sample of ${data.candidates}, grown from ${graphChoice().focus || 'the first by name'}`
      + ' (choose a class or an individual to look around it)'
    : data.inferred_links === false
      ? `${shown}. Links as asserted (read without waiting for the reasoner; an individual's page shows`
        + ' inferred ones). Colour: most specific type.'
      : `${shown}. Solid: asserted; dashed: inferred. Colour: most specific type.`;
  if (!window.cytoscape) {
    note.textContent = 'The graph library is missing (armor_service/web/static/vendor): run make setup.';
    return;
  }
  const elements = [];
  const types = new Map();
  for (const node of data.nodes) {
    const type = node.types.length ? node.types.map((t) => t.name).join(', ') : 'Thing';
    types.set(type, colourOf(type));
    elements.push({group: 'nodes', data: {id: node.iri, label: `${node.name}\n${type}`, colour: colourOf(type)}});
  }
  for (const edge of data.edges) {
    elements.push({group: 'edges', data: {id: `${edge.source} ${edge.property} ${edge.target}`,
      source: edge.source, target: edge.target, label: edge.property_name,
      line: edge.asserted ? 'solid' : 'dashed', arrow: edge.both_ways ? 'none' : 'triangle'}});
  }
  const first = graph === null;
  if (first) {
    graph = cytoscape({
      container: $('#graph-canvas'),
      minZoom: 0.1,
      maxZoom: 4,
      style: [
        {selector: 'node', style: {
          'background-color': 'data(colour)', 'label': 'data(label)', 'text-wrap': 'wrap',
          'font-size': LABEL_PX.node, 'text-valign': 'bottom', 'text-margin-y': 4, 'width': 40,
          'height': 40, 'color': '#1d2330', 'text-background-color': '#ffffff',
          'text-background-opacity': 0.7, 'min-zoomed-font-size': 7}},
        // Edge labels level and on a background of their own, beside the line rather than on it.
        {selector: 'edge', style: {
          'width': 3, 'line-color': '#98a2b3', 'line-style': 'data(line)', 'curve-style': 'bezier',
          // Links both ways between two individuals bow apart far enough for both labels.
          'control-point-step-size': 70,
          'target-arrow-shape': 'data(arrow)', 'target-arrow-color': '#98a2b3', 'label': 'data(label)',
          'font-size': LABEL_PX.edge, 'color': '#344054', 'text-rotation': 'none',
          'text-background-color': '#ffffff', 'text-background-opacity': 0.85,
          'text-background-shape': 'roundrectangle', 'text-background-padding': 2,
          'min-zoomed-font-size': 7}},
        {selector: 'node:selected', style: {'border-width': 3, 'border-color': '#2458b3'}},
      ],
    });
    graph.on('tap', 'node', (event) => showIndividual(event.target.id()));
    graph.on('zoom', keepLabelsReadable);
  }
  // Links that come and go (someone moves to another room) leave the map where it is; only
  // individuals that appear or go make a new layout, started from the current positions.
  const wanted = new Set(elements.map((e) => e.data.id));
  let nodesChanged = first;
  graph.batch(() => {
    graph.elements().forEach((existing) => {
      if (!wanted.has(existing.id())) {
        nodesChanged = nodesChanged || existing.isNode();
        existing.remove();
      }
    });
    for (const element of elements) {
      const existing = graph.getElementById(element.data.id);
      if (existing.nonempty()) {
        // Only what changed is restyled and redrawn: most of a map stays as it was.
        const old = existing.data();
        if (Object.keys(element.data).some((key) => old[key] !== element.data[key])) {
          existing.data(element.data);
        }
      } else {
        graph.add(element);
        nodesChanged = nodesChanged || element.group === 'nodes';
      }
    }
  });
  if (nodesChanged) layOut(first);
  fill($('#graph-legend'), ...[...types].sort().map(([type, colour]) =>
    el('span', {}, el('span', {className: 'swatch', style: `background:${colour}`}), type)));
}

// ---------------------------------------------------------------- class hierarchy
const classesRefresher = new Refresher(async () => {
  const name = state.selected;
  const tree = $('#class-tree');
  let hierarchy;
  try {
    hierarchy = await api(referencePath('/classes'));
  } catch (error) {
    showError(tree, error);
    return;
  }
  if (name !== state.selected) return;
  renderClassTree(hierarchy);
});

// Small hierarchies are shown whole; large ones open a class at a time.
const OPEN_HIERARCHY_MAX_CLASSES = 200;
let classChildren = new Map();
let classByIri = new Map();
let hierarchyOpen = false;

function renderClassTree(hierarchy) {
  classChildren = new Map();
  classByIri = new Map();
  hierarchyOpen = hierarchy.classes.length <= OPEN_HIERARCHY_MAX_CLASSES;
  const roots = [];
  for (const owlClass of hierarchy.classes) {
    classByIri.set(owlClass.iri, owlClass);
    if (!owlClass.parents.length) roots.push({owlClass, asserted: true});
    for (const parent of owlClass.parents) {
      if (!classChildren.has(parent.iri)) classChildren.set(parent.iri, []);
      classChildren.get(parent.iri).push({owlClass, asserted: parent.asserted, parent: parent.iri});
    }
  }
  const heading = el('p', {className: 'muted', text: hierarchy.inferred
    ? 'Inferred hierarchy. Green: stated in the ontology; purple, italic: inferred by the reasoner.'
    : 'Asserted hierarchy only: the reasoner cannot answer for this reference.'});
  const top = el('ul', {});
  appendClassItems(top, [{owlClass: {iri: 'owl:Thing', name: 'Thing', equivalents: [], unsatisfiable: false},
    asserted: true, children: roots}], new Set());
  fill($('#class-tree'), heading, top);
}

/** Appends one <li> per class; a class's children are built when it is opened (large hierarchies). */
function appendClassItems(list, items, ancestors) {
  for (const {owlClass, asserted, children, parent} of items.sort((a, b) => a.owlClass.name.localeCompare(b.owlClass.name))) {
    const kids = children || classChildren.get(owlClass.iri) || [];
    const label = el('span', {className: `class-name ${owlClass.unsatisfiable ? 'unsatisfiable' : ''}`},
      el('span', {className: asserted ? 'asserted' : 'inferred', 'data-iri': owlClass.iri, text: owlClass.name}),
      asserted ? null : el('span', {className: 'tag', text: '(inferred)'}),
      asserted || !parent || parent === 'owl:Thing' ? null : whyButton('subclass', [owlClass.iri, parent]),
      owlClass.equivalents.length ? el('span', {className: 'tag',
        text: '≡ ' + owlClass.equivalents.map((e) => e.name).join(', ')}) : null,
      owlClass.unsatisfiable ? el('span', {className: 'tag unsatisfiable', text: '⚠ unsatisfiable'}) : null);
    const selected = owlClass.iri === state.classIri;
    if (!kids.length || ancestors.has(owlClass.iri)) {
      list.append(el('li', {className: `leaf${selected ? ' selected' : ''}`, 'data-iri': owlClass.iri}, label));
      continue;
    }
    const open = owlClass.iri === 'owl:Thing' || state.openClasses.has(owlClass.iri)
      || (hierarchyOpen && !state.closedClasses.has(owlClass.iri));
    const details = el('details', {'data-iri': owlClass.iri, open},
      el('summary', {'data-iri': owlClass.iri}, label));
    details.armorChildren = kids;
    details.armorAncestors = new Set([...ancestors, owlClass.iri]);
    if (open) fillClassChildren(details);
    list.append(el('li', {className: selected ? 'selected' : ''}, details));
  }
}

function fillClassChildren(details) {
  if (details.armorFilled) return;
  details.armorFilled = true;
  const list = el('ul', {});
  appendClassItems(list, details.armorChildren, details.armorAncestors);
  details.append(list);
}

const classDetailRefresher = new Refresher(async () => {
  const iri = state.classIri;
  const panel = $('#class-detail');
  if (!iri || iri === 'owl:Thing') return;
  let owlClass;
  try {
    owlClass = await api(referencePath('/class?iri=' + encodeURIComponent(iri)));
  } catch (error) {
    showError(panel, error);
    return;
  }
  if (iri !== state.classIri) return;
  const frame = (title, lines) => [el('dt', {text: title}), el('dd', {},
    lines.length ? lines.map((line) => el('div', {className: 'manchester', text: line}))
      : el('span', {className: 'muted', text: 'none'}))];
  fill(panel,
    el('h3', {}, owlClass.name, owlClass.unsatisfiable ? el('span', {className: 'badge bad', text: 'unsatisfiable'})
      : null),
    el('dl', {},
      frame('EquivalentTo', owlClass.equivalent_to),
      frame('SubClassOf', owlClass.subclass_of),
      frame('DisjointWith', owlClass.disjoint_with),
      frame('Restrictions', owlClass.restrictions),
      owlClass.annotations.length ? frame('Annotations', owlClass.annotations) : [],
      el('dt', {text: 'Superclasses (inferred)'}), el('dd', {}, entityList(owlClass.inferred_superclasses, 'class')),
      el('dt', {text: `Instances (${owlClass.instance_count})`}),
      el('dd', {}, entityList(owlClass.instances, 'individual'),
        owlClass.instance_count > owlClass.instances.length
          ? el('div', {className: 'muted', text: `the first ${owlClass.instances.length} by name`}) : null)));
});

function showClass(iri) {
  state.classIri = iri;
  if (state.tab !== 'classes') select(state.selected, 'classes');
  else classesRefresher.request();
  classDetailRefresher.request();
}

// ---------------------------------------------------------------- individuals
const individualsRefresher = new Refresher(async () => {
  const name = state.selected;
  const query = new URLSearchParams({search: state.individualSearch, offset: state.individualOffset,
    limit: PAGE_SIZE});
  const body = $('#individuals-table tbody');
  let page;
  try {
    page = await api(referencePath('/individuals?' + query));
  } catch (error) {
    fill(body, el('tr', {}, el('td', {colspan: 2, className: 'error', text: error.message})));
    return;
  }
  if (name !== state.selected) return;
  const last = Math.min(page.offset + page.individuals.length, page.total);
  $('#individual-count').textContent = page.total
    ? `${page.offset + 1}–${last} of ${page.total.toLocaleString()}` : 'no individual matches';
  $('#individual-previous').disabled = page.offset === 0;
  $('#individual-next').disabled = last >= page.total;
  fill(body, ...page.individuals.map((individual) => el('tr', {'data-iri': individual.iri,
    'data-name': individual.name, className: individual.iri === state.individualIri ? 'selected' : ''},
  el('td', {text: individual.name}),
  el('td', {className: 'types'}, entityList(individual.types, 'class')))));
});

const individualDetailRefresher = new Refresher(async () => {
  const iri = state.individualIri;
  const panel = $('#individual-detail');
  if (!iri) return;
  let individual;
  try {
    individual = await api(referencePath('/individual?iri=' + encodeURIComponent(iri)));
  } catch (error) {
    showError(panel, error);
    return;
  }
  if (iri !== state.individualIri) return;
  const values = (entries, render) => entries.length ? entries.map((entry) => [
    el('dt', {text: entry.property.name}), el('dd', {}, render(entry.values, entry))])
    : [el('dd', {className: 'muted', text: 'none'})];
  fill(panel,
    el('h3', {text: individual.name}),
    el('dl', {},
      el('dt', {text: 'Types'}), el('dd', {}, entityList(individual.types, 'class',
        (type) => whyButton('instance', [individual.iri, type.iri]))),
      individual.same_as.length ? [el('dt', {text: 'Same as'}), el('dd', {}, entityList(individual.same_as,
        'individual'))] : [],
      el('dt', {text: 'Object properties'}),
      values(individual.object_values, (v, entry) => entityList(v, 'individual',
        (value) => whyButton('objectprop', [entry.property.iri, individual.iri, value.iri]))),
      el('dt', {text: 'Data properties'}),
      values(individual.data_values, (v) => el('span', {className: 'entity-list'}, v.map((item) =>
        el('span', {className: item.asserted ? 'asserted' : 'inferred', text: item.value}))))),
    individual.inferred ? null : el('p', {className: 'muted', text: 'Asserted facts only: the reasoner '
      + 'cannot answer for an inconsistent reference.'}));
});

function showIndividual(iri) {
  state.individualIri = iri;
  if (state.tab !== 'individuals') {
    state.individualSearch = shortName(iri);
    $('#individual-search').value = state.individualSearch;
    state.individualOffset = 0;
    select(state.selected, 'individuals');
  } else {
    individualsRefresher.request();
  }
  individualDetailRefresher.request();
}

// ---------------------------------------------------------------- DL and SPARQL
function directiveFailure(answer) {
  return el('p', {className: 'error', text: `${answer.description} (exit code ${answer.exit_code})`});
}

async function askDl(expression) {
  const result = $('#dl-result');
  fill(result, el('p', {className: 'muted', text: 'asking…'}));
  try {
    const answer = await postJson(referencePath('/dl'), {expression});
    // A success may say something: a word of the expression the reference does not know.
    const part = (title, reply, kind) => [el('h3', {text: title}), reply.success
      ? [reply.description ? el('p', {className: 'note', text: reply.description}) : null,
        entityList(reply.items.map((item) => ({iri: item.replace(/^<|>$/g, ''), name: shortName(item)})), kind)]
      : directiveFailure(reply)];
    fill(result, ...part('Instances', answer.instances, 'individual'),
      ...part('Subclasses', answer.subclasses, 'class'));
  } catch (error) {
    showError(result, error);
  }
}

async function runSparql(query) {
  const result = $('#sparql-result');
  fill(result, el('p', {className: 'muted', text: 'running…'}));
  try {
    const answer = await postJson(referencePath('/sparql'), {query});
    if (!answer.success) {
      fill(result, directiveFailure(answer));
      return;
    }
    const rows = [[]];
    for (const [key, value] of answer.cells) {
      if (key === '') rows.push([]);
      else rows[rows.length - 1].push([key, value]);
    }
    const filled = rows.filter((row) => row.length);
    const columns = filled.length ? filled[0].map(([key]) => key) : [];
    fill(result,
      el('p', {className: 'muted',
        text: `${filled.length} row(s)${answer.timeout ? ', cut short by the time limit' : ''}`}),
      el('table', {}, el('thead', {}, el('tr', {}, columns.map((c) => el('th', {text: c})))),
        el('tbody', {}, filled.map((row) => el('tr', {}, row.map(([, value]) => el('td', {title: value,
          text: value.startsWith('<') ? shortName(value) : value})))))));
  } catch (error) {
    showError(result, error);
  }
}

// ---------------------------------------------------------------- recent directives
const recentRefresher = new Refresher(async () => {
  const name = state.selected;
  const query = new URLSearchParams({reference: name, limit: 100});
  if ($('#recent-all').checked) query.set('all', '1');
  const body = $('#recent-table tbody');
  let recent;
  try {
    recent = await api('/api/recent?' + query);
  } catch (error) {
    fill(body, el('tr', {}, el('td', {colspan: 6, className: 'error', text: error.message})));
    return;
  }
  if (name !== state.selected) return;
  fill(body, ...recent.directives.map((d) => el('tr', {},
    el('td', {text: clock(d.at_ms)}), el('td', {text: d.client || '(no name)'}), el('td', {text: d.command}),
    el('td', {className: 'manchester', text: d.args.join(', ')}),
    el('td', {className: d.success ? '' : 'fail', text: String(d.exit_code)}),
    el('td', {text: `${d.latency_ms.toFixed(1)} ms`}))));
});

const tabRefreshers = {
  graph: graphRefresher,
  classes: classesRefresher,
  individuals: individualsRefresher,
  query: new Refresher(async () => {}),
  recent: recentRefresher,
};

// ---------------------------------------------------------------- live updates
let socketDelayMs = 500;

function connectLive() {
  const socket = new WebSocket(`${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/api/live`);
  const status = $('#connection');
  socket.onopen = () => {
    socketDelayMs = 500;
    status.className = 'connection live';
    status.textContent = 'live';
  };
  socket.onmessage = (message) => onRevisions(JSON.parse(message.data));
  socket.onclose = () => {
    status.className = 'connection offline';
    status.textContent = 'reconnecting…';
    state.revisions = null;
    setTimeout(connectLive, socketDelayMs);
    socketDelayMs = Math.min(socketDelayMs * 2, 10000);
  };
}

/** The node's table of revisions: refetch what shows a reference whose revision moved. */
function onRevisions(table) {
  const before = state.revisions;
  const answeredBefore = state.answered;
  state.revisions = table.references;
  state.answered = table.answered || {};
  // Queries and refused directives move no revision, yet belong on the recent-directives list.
  if (before !== null && state.tab === 'recent'
      && answeredBefore[state.selected] !== state.answered[state.selected]) {
    recentRefresher.request();
  }
  if (before === null) {
    // First table since (re)connecting: anything may have changed meanwhile.
    overviewRefresher.request();
    refreshSelected();
    return;
  }
  const names = new Set([...Object.keys(before), ...Object.keys(table.references)]);
  const revision = (references, name) => (references[name] || {}).revision;
  const changed = [...names].filter((name) => revision(before, name) !== revision(table.references, name));
  if (!changed.length) return;
  overviewRefresher.request();
  if (changed.includes(state.selected)) {
    refreshSelected();
    if (!summaryOf(state.selected)?.consistent) consistencyRefresher.request();
  }
}

// ---------------------------------------------------------------- events
function wire() {
  $('#reference-list').addEventListener('click', (event) => {
    const card = event.target.closest('.card');
    if (card) select(card.dataset.name, null);
  });
  document.querySelector('.tabs').addEventListener('click', (event) => {
    const button = event.target.closest('button[data-tab]');
    if (button) select(state.selected, button.dataset.tab);
  });
  document.body.addEventListener('click', (event) => {
    const why = event.target.closest('button.why');
    if (why) {
      event.preventDefault();
      showWhy(why);
      return;
    }
    const link = event.target.closest('a.entity');
    if (!link) return;
    event.preventDefault();
    if (link.dataset.kind === 'class') showClass(link.dataset.iri);
    else showIndividual(link.dataset.iri);
  });
  const tree = $('#class-tree');
  tree.addEventListener('toggle', (event) => {
    const details = event.target;
    if (!(details instanceof HTMLDetailsElement)) return;
    if (details.open) {
      state.openClasses.add(details.dataset.iri);
      state.closedClasses.delete(details.dataset.iri);
      fillClassChildren(details);
    } else {
      state.openClasses.delete(details.dataset.iri);
      state.closedClasses.add(details.dataset.iri);
    }
  }, true);
  tree.addEventListener('click', (event) => {
    // The name selects the class; the disclosure triangle beside it opens and closes.
    const name = event.target.closest('span[data-iri]');
    if (!name || name.dataset.iri === 'owl:Thing') return;
    event.preventDefault();
    for (const old of tree.querySelectorAll('.selected')) old.classList.remove('selected');
    name.closest('li').classList.add('selected');
    state.classIri = name.dataset.iri;
    classDetailRefresher.request();
  });
  $('#individuals-table tbody').addEventListener('click', (event) => {
    const row = event.target.closest('tr[data-iri]');
    if (!row || event.target.closest('a.entity')) return;
    for (const old of row.parentElement.querySelectorAll('.selected')) old.classList.remove('selected');
    row.classList.add('selected');
    state.individualIri = row.dataset.iri;
    individualDetailRefresher.request();
  });
  let searchTimer = null;
  $('#individual-search').addEventListener('input', (event) => {
    clearTimeout(searchTimer);
    searchTimer = setTimeout(() => {
      state.individualSearch = event.target.value;
      state.individualOffset = 0;
      individualsRefresher.request();
    }, 250);
  });
  $('#individual-previous').addEventListener('click', () => {
    state.individualOffset = Math.max(0, state.individualOffset - PAGE_SIZE);
    individualsRefresher.request();
  });
  $('#individual-next').addEventListener('click', () => {
    state.individualOffset += PAGE_SIZE;
    individualsRefresher.request();
  });
  $('#graph-form').addEventListener('submit', (event) => {
    event.preventDefault();
    const form = event.target;
    const checked = [...form.querySelectorAll('input[name=property]:checked')].map((box) => box.value);
    state.graphChoice = {properties: checked, class: form.elements.class.value.trim(),
      focus: form.elements.focus.value.trim(), limit: Number(form.elements.limit.value) || 300};
    graphRefresher.request();
  });
  $('#dl-form').addEventListener('submit', (event) => {
    event.preventDefault();
    askDl($('#dl-expression').value);
  });
  $('#sparql-form').addEventListener('submit', (event) => {
    event.preventDefault();
    runSparql($('#sparql-query').value);
  });
  $('#recent-all').addEventListener('change', () => recentRefresher.request());
  window.addEventListener('hashchange', () => {
    const [name, tab] = location.hash.slice(2).split('/').map(decodeURIComponent);
    if (summaryOf(name) && (name !== state.selected || (TABS.includes(tab) && tab !== state.tab))) {
      select(name, TABS.includes(tab) ? tab : null);
    }
  });
  // A lease counts down without asking the node.
  setInterval(() => {
    if (state.overview.some((r) => r.lease_left_s !== undefined)) {
      renderReferenceList();
      renderSummary();
    }
  }, 1000);
}

// For the browser tests and anyone at the console: the graph as cytoscape holds it.
window.armorWeb = {graph: () => graph, settled: () => layoutSettled};

document.addEventListener('DOMContentLoaded', () => {
  const tab = location.hash.slice(2).split('/')[1];
  if (TABS.includes(tab)) state.tab = tab;
  wire();
  overviewRefresher.request();
  connectLive();
});
