// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
// Lays the graph out off the page's thread: cytoscape's force-directed layout (cose) on a
// headless copy of the graph, so a page showing a thousand individuals never freezes while they
// settle. Asked {id, elements, randomize, numIter}; answers {id, positions: [[node id, {x, y}]]}.
'use strict';
importScripts('/static/vendor/cytoscape.min.js');

// Set so that a floor plan reads as one: strong repulsion and short links keep each room beside
// its own corridor (tests/integration/test_web_view.py checks it on 4 corridors of 8 rooms).
const MAP_LAYOUT = {name: 'cose', animate: false, fit: false, nodeRepulsion: () => 300000,
  idealEdgeLength: () => 40, edgeElasticity: () => 200, gravity: 1, componentSpacing: 60};

onmessage = (event) => {
  const {id, elements, randomize, numIter} = event.data;
  const graph = cytoscape({headless: true, styleEnabled: true, elements,
    style: [{selector: 'node', style: {width: 40, height: 40}}]});
  graph.layout({...MAP_LAYOUT, randomize, numIter}).run();
  const positions = graph.nodes().map((node) => [node.id(), node.position()]);
  graph.destroy();
  postMessage({id, positions});
};
