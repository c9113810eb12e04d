// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
// The Scenes tab of the web view (docs/scenes.md): the scene classes a reference has learned by
// demonstration, each under the scenes it contains and defined in words, and the last scenes it
// was shown, each recognition explained by the relations that meet the class's restrictions.
// Loaded after app.js, whose helpers (el, fill, api, referencePath, Refresher, entityLink) it
// uses; it adds its tab to app.js's table of tabs. Like app.js it computes nothing about
// ontologies: the SIT plugin answers QUERY SIT SCENES and QUERY SIT RECENT.
'use strict';

/** An answered class (<iri> or a short name) as app.js's links want it. */
function sceneEntity(rendered) {
  const iri = rendered.startsWith('<') && rendered.endsWith('>') ? rendered.slice(1, -1) : rendered;
  return {iri, name: shortName(rendered)};
}

// Definitions longer than this start folded (a click opens them).
const OPEN_DEFINITION_MAX = 6;

/** A class's definition in words, one restriction a line; folded when long or shown before. */
function sceneDefinition(sceneClass, shownBefore) {
  const count = sceneClass.restrictions.length;
  return el('details', {className: 'scene-definition', open: !shownBefore && count <= OPEN_DEFINITION_MAX},
    el('summary', {className: 'muted', text: `defined by ${count} restriction${count === 1 ? '' : 's'}`
      + (shownBefore ? ' (also listed above)' : '')}),
    el('ul', {}, sceneClass.restrictions.map((r) =>
      el('li', {title: `${r.property} min ${r.min} ${r.type}`, text: r.words}))));
}

/** The learned classes as a tree: each class under every learned class it is a subclass of. */
function renderSceneClasses(container, classes) {
  if (!classes.length) {
    fill(container, el('h3', {text: 'Learned scenes'}),
      el('p', {className: 'muted', text: 'No scene learned in this reference yet: send one to '
        + 'sit_armor_injected (or SIT SCENE) and its class appears here.'}));
    return;
  }
  const byName = new Map(classes.map((c) => [c.class, c]));
  const children = new Map();
  const roots = [];
  for (const sceneClass of classes) {
    const parents = sceneClass.superscenes.filter((p) => byName.has(p));
    if (!parents.length) roots.push(sceneClass);
    for (const parent of parents) {
      if (!children.has(parent)) children.set(parent, []);
      children.get(parent).push(sceneClass);
    }
  }
  const shown = new Set();
  const item = (sceneClass, ancestors) => {
    const below = ancestors.has(sceneClass.class) ? [] : children.get(sceneClass.class) || [];
    const inside = new Set([...ancestors, sceneClass.class]);
    const shownBefore = shown.has(sceneClass.class);
    shown.add(sceneClass.class);
    return el('li', {'data-scene': sceneClass.name},
      el('div', {className: 'scene-head'},
        entityLink(sceneEntity(sceneClass.class), 'class'),
        el('span', {className: 'tag', text: `cardinality ${sceneClass.cardinality}`}),
        sceneClass.equivalent.length
          ? el('span', {className: 'tag', text: '≡ ' + sceneClass.equivalent.map(shortName).join(', ')}) : null),
      sceneDefinition(sceneClass, shownBefore),
      below.length ? el('ul', {}, below.map((child) => item(child, inside))) : null);
  };
  fill(container, el('h3', {text: `Learned scenes (${classes.length})`}),
    el('p', {className: 'muted', text: 'Each scene is listed under the scenes it contains: the '
      + 'reasoner found its definition implies theirs.'}),
    el('ul', {className: 'scene-tree'}, roots.map((root) => item(root, new Set()))));
}

function sceneExplanation(recognition) {
  if (!recognition.explanation) {
    return el('p', {className: 'muted', text: 'Not a learned scene class: the reasoner found it from '
      + 'other axioms of the ontology.'});
  }
  return el('table', {className: 'scene-explanation'},
    el('thead', {}, el('tr', {}, el('th', {text: 'restriction of the class'}),
      el('th', {text: 'relations of the scene that meet it'}), el('th', {text: 'elements'}))),
    el('tbody', {}, recognition.explanation.map((match) => el('tr', {},
      el('td', {text: match.restriction}),
      el('td', {className: 'manchester', text: match.relations.join('; ')}),
      el('td', {className: match.counted >= match.min ? 'met' : 'fail',
        text: `${match.counted} of at least ${match.min}`})))));
}

/** SPHERE#1 at (0.00, 0.10, 0.05), with its axis when it has one: centimetres are what matter. */
function elementText(element) {
  const triple = (values) => `(${values.map((v) => v.toFixed(2)).join(', ')})`;
  const f = element.features;
  return `${element.label} at ${triple(f.slice(0, 3))}` + (f.length === 6 ? ` axis ${triple(f.slice(3))}` : '');
}

function renderRecentScenes(container, scenes) {
  if (!scenes.length) {
    fill(container, el('h3', {text: 'Recent scenes'}),
      el('p', {className: 'muted', text: 'No scene shown to this reference since the node started.'}));
    return;
  }
  fill(container, el('h3', {text: 'Recent scenes'}), scenes.map((scene) => el('div', {className: 'scene-card'},
    el('div', {className: 'muted'}, `${clock(scene.at_ms)} · ${scene.client || '(no name)'} · `
      + `${scene.elements.length} elements, cardinality ${scene.cardinality}`),
    el('div', {className: 'manchester'}, scene.elements.map((e) =>
      el('span', {className: 'scene-element', text: elementText(e)}))),
    scene.learned
      ? el('details', {className: 'scene-learned'},
        el('summary', {}, 'learned ', entityLink(sceneEntity(scene.learned), 'class')),
        el('div', {className: 'muted', text: scene.learned_definition}))
      : el('div', {className: 'muted', text: scene.cardinality ? 'nothing learned' : 'no relation: nothing learned'}),
    scene.recognitions.map((recognition) => el('details', {className: 'scene-recognition'},
      el('summary', {}, 'recognised as ', el('strong', {text: recognition.name}),
        ` similarity ${recognition.similarity.toFixed(3)}`,
        recognition.cardinality !== undefined
          ? el('span', {className: 'muted', text: ` (${recognition.cardinality} of ${scene.cardinality}) · why?`}) : null),
      sceneExplanation(recognition))))));
}

const scenesRefresher = new Refresher(async () => {
  const name = state.selected;
  const classesPane = $('#scene-classes');
  const recentPane = $('#scene-recent');
  let classes;
  let recent;
  try {
    [classes, recent] = await Promise.all([api(referencePath('/scenes')), api(referencePath('/scenes/recent'))]);
  } catch (error) {
    showError(classesPane, error.status === 400
      ? new Error(`${error.message}: is the SIT plugin loaded (plugin_dirs)?`) : error);
    fill(recentPane);
    return;
  }
  if (name !== state.selected) return;
  // Keep open what the reader opened: recognitions are keyed by scene time and class.
  const opened = new Set([...recentPane.querySelectorAll('details[open]')].map((d) => d.dataset.key));
  renderSceneClasses(classesPane, classes.items);
  renderRecentScenes(recentPane, recent.items);
  recentPane.querySelectorAll('.scene-card').forEach((card, index) => {
    card.querySelectorAll('details').forEach((details, position) => {
      details.dataset.key = `${recent.items[index].at_ms}/${position}`;
      if (opened.has(details.dataset.key)) details.open = true;
    });
  });
});

TABS.push('scenes');
tabRefreshers.scenes = scenesRefresher;
