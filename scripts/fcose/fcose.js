#!/usr/bin/env node
// Lays out a scene with Cytoscape.js fCoSE, optionally with communities as compound
// (parent) nodes, and prints one JSON line:
//   {"positions": [[x,y],...], "ms": T, "boxes": [[minx,miny,maxx,maxy],...]}
// positions in the scene's node order; boxes the parents' bounding boxes in community
// index order (null for an index with no members; empty without a communities file).
//
// usage: node fcose.js SCENE.json [COMMUNITIES.json] [--seed S]
'use strict';

const fs = require('fs');

function usage(msg) {
  if (msg) process.stderr.write(msg + '\n');
  process.stderr.write('usage: node fcose.js SCENE.json [COMMUNITIES.json] [--seed S]\n');
  process.exit(2);
}

const files = [];
let seed = 1;
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i++) {
  if (argv[i] === '--seed') {
    if (i + 1 >= argv.length) usage('--seed needs a value');
    seed = Number(argv[++i]);
    if (!Number.isInteger(seed)) usage('--seed must be an integer');
  } else if (argv[i].startsWith('--')) {
    usage('unknown option ' + argv[i]);
  } else {
    files.push(argv[i]);
  }
}
if (files.length < 1 || files.length > 2) usage();

// Deterministic runs: replace Math.random (used by fCoSE's spectral sampling and
// cose-base) with a seeded mulberry32 before the libraries are loaded or run.
// (layout-base's own RandomSeed is already deterministic per process.)
let state = (seed ^ 0x9e3779b9) >>> 0;
Math.random = function mulberry32() {
  state = (state + 0x6d2b79f5) >>> 0;
  let t = state;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};

const cytoscape = require('cytoscape');
const fcose = require('cytoscape-fcose');
cytoscape.use(fcose);

const scene = JSON.parse(fs.readFileSync(files[0], 'utf8'));
const nodes = scene.nodes;
const indexOf = new Map(nodes.map((n, i) => [n.id, i]));
if (indexOf.size !== nodes.length) usage('duplicate node ids in ' + files[0]);

let community = null;
if (files.length === 2) {
  community = JSON.parse(fs.readFileSync(files[1], 'utf8')).community;
  if (!Array.isArray(community) || community.length !== nodes.length) {
    usage(`${files[1]}: "community" must list one index per node (${nodes.length})`);
  }
}

const elements = [];
const parents = []; // community indices that have members, ascending
if (community) {
  const k = Math.max(-1, ...community) + 1;
  const used = new Array(k).fill(false);
  for (const c of community) used[c] = true;
  for (let c = 0; c < k; c++) {
    if (used[c]) {
      parents.push(c);
      elements.push({ group: 'nodes', data: { id: 'c' + c } });
    }
  }
}
nodes.forEach((n, i) => {
  const data = { id: 'n' + i, d: 2 * n.radius };
  if (community) data.parent = 'c' + community[i];
  // Initial positions are irrelevant with randomize: true, but give the scene's.
  elements.push({ group: 'nodes', data, position: { x: n.x || 0, y: n.y || 0 } });
});
scene.edges.forEach(([a, b], j) => {
  if (!indexOf.has(a) || !indexOf.has(b)) usage(`edge ${j} names an unknown node id`);
  elements.push({
    group: 'edges',
    data: { id: 'e' + j, source: 'n' + indexOf.get(a), target: 'n' + indexOf.get(b) },
  });
});

const cy = cytoscape({
  headless: true,
  styleEnabled: true,
  elements,
  style: [
    { selector: 'node', style: { shape: 'ellipse', label: '' } },
    { selector: 'node:childless', style: { width: 'data(d)', height: 'data(d)' } },
    { selector: 'node:parent', style: { padding: 0, 'border-width': 0 } },
  ],
});

const layout = cy.layout({
  name: 'fcose',
  quality: 'proof',
  randomize: true,
  animate: false,
  fit: false,
  packComponents: true,
  nodeDimensionsIncludeLabels: false,
});
const t0 = process.hrtime.bigint();
layout.run();
const ms = Number(process.hrtime.bigint() - t0) / 1e6;

const positions = nodes.map((_, i) => {
  const p = cy.getElementById('n' + i).position();
  return [p.x, p.y];
});
const k = community ? Math.max(-1, ...community) + 1 : 0;
const boxes = Array.from({ length: k }, (_, c) => {
  if (!parents.includes(c)) return null; // a community index with no members
  const bb = cy.getElementById('c' + c).boundingBox({ includeLabels: false, includeOverlays: false });
  return [bb.x1, bb.y1, bb.x2, bb.y2];
});

// Headless with styleEnabled runs an animation loop until destroyed (see
// cytoscape's headlessStep); without this the process never exits.
cy.destroy();

process.stdout.write(JSON.stringify({ positions, ms: Math.round(ms * 10) / 10, boxes }) + '\n');
