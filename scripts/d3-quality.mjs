// d3-force v3 on the shipped scenes: link distance 100, default many-body, collide at the
// node radius, centre. Prints edge-length CV, overlapping pairs, crossings, ticks to
// settle (d3 stops when alpha < alphaMin: 300 ticks) and the mean tick time.
//
//   cd scripts && npm install && node d3-quality.mjs [--starts N] [--ticks N] [scene ...]
//
// Scenes are read from `scenes/`, or from `target/scenes/` where the `quality` example
// writes generated ones (`cargo run --release --example quality -- --write-scenes
// ba_n10000_m2`). `--ticks N` stops after N ticks (to time the tick of a huge graph).
//
// `--starts N` lays each scene out N times, from the file's positions and then from N - 1
// copies jittered by up to half a unit, with the same sequence as the `quality` example
// (`cargo run --release --example quality -- --starts N`), and prints the spread.
import { existsSync, readFileSync } from "node:fs";
import { forceSimulation, forceLink, forceManyBody, forceCollide, forceCenter } from "d3-force";

const args = process.argv.slice(2);
let starts = 1;
const startsAt = args.indexOf("--starts");
if (startsAt >= 0) {
  starts = Number(args[startsAt + 1]);
  args.splice(startsAt, 2);
}
let maxTicks = Infinity;
const ticksAt = args.indexOf("--ticks");
if (ticksAt >= 0) {
  maxTicks = Number(args[ticksAt + 1]);
  args.splice(ticksAt, 2);
}
const scenes = args.length > 0 ? args
  : ["karate", "les_miserables", "florentine", "n200_e500", "tree_1023", "grid_30x30", "n1000_e2500", "n10000_e25000"];

// The quality example's jitter: a 64-bit LCG, the top 24 bits of each state as an offset.
function jitter(nodes, start) {
  if (start === 0) return;
  const mask = (1n << 64n) - 1n;
  let seed = BigInt(start);
  const next = () => {
    seed = (seed * 6364136223846793005n + 1442695040888963407n) & mask;
    return Number(seed >> 40n) / 2 ** 24 - 0.5;
  };
  for (const n of nodes) {
    n.x += next();
    n.y += next();
  }
}

function measure(nodes, links) {
  const lengths = links.map((l) => Math.hypot(l.source.x - l.target.x, l.source.y - l.target.y));
  const mean = lengths.reduce((a, b) => a + b, 0) / lengths.length;
  const sd = Math.sqrt(lengths.reduce((a, l) => a + (l - mean) ** 2, 0) / lengths.length);
  // Overlapping pairs (deeper than half a unit), found on a grid of cells two radii wide,
  // as `quality::overlapping_pairs` does.
  let overlaps = 0;
  const cell = 2 * Math.max(1, ...nodes.map((n) => n.radius));
  const grid = new Map();
  const key = (x, y) => `${Math.floor(x / cell)},${Math.floor(y / cell)}`;
  nodes.forEach((n, i) => {
    const k = key(n.x, n.y);
    if (!grid.has(k)) grid.set(k, []);
    grid.get(k).push(i);
  });
  nodes.forEach((n, i) => {
    const [cx, cy] = [Math.floor(n.x / cell), Math.floor(n.y / cell)];
    for (let dx = -1; dx <= 1; dx++)
      for (let dy = -1; dy <= 1; dy++)
        for (const j of grid.get(`${cx + dx},${cy + dy}`) ?? [])
          if (j > i && Math.hypot(n.x - nodes[j].x, n.y - nodes[j].y) - n.radius - nodes[j].radius < -0.5) overlaps++;
  });
  let crossings = 0;
  if (links.length <= 3000) {
    const o = (a, b, c) => (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    for (let i = 0; i < links.length; i++)
      for (let j = i + 1; j < links.length; j++) {
        const [p1, q1, p2, q2] = [links[i].source, links[i].target, links[j].source, links[j].target];
        if (p1 === p2 || p1 === q2 || q1 === p2 || q1 === q2) continue;
        if (o(p1, q1, p2) * o(p1, q1, q2) < 0 && o(p2, q2, p1) * o(p2, q2, q1) < 0) crossings++;
      }
  }
  return { cv: sd / mean, mean, overlaps, crossings };
}

function layout(scene, start) {
  const nodes = scene.nodes.map((n) => ({ id: n.id, x: n.x, y: n.y, radius: n.radius || 16 }));
  jitter(nodes, start);
  const links = scene.edges.filter(([a, b]) => a !== b).map(([source, target]) => ({ source, target }));
  const sim = forceSimulation(nodes)
    .force("link", forceLink(links).id((d) => d.id).distance(100))
    .force("charge", forceManyBody())
    .force("collide", forceCollide((d) => d.radius))
    .force("center", forceCenter(0, 0))
    .stop();
  let ticks = 0;
  const started = process.hrtime.bigint();
  while (sim.alpha() >= sim.alphaMin() && ticks < maxTicks) { sim.tick(); ticks++; }
  const ms = Number(process.hrtime.bigint() - started) / 1e6 / ticks;
  return { ticks, ms, nodes, links, ...measure(nodes, links) };
}

if (starts === 1) {
  console.log("| scene | ticks | edge-length CV | mean edge | overlaps | crossings | ms per tick |");
  console.log("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
} else {
  console.log("| scene | starts | edge-length CV mean | CV min-max | overlaps (all starts) |");
  console.log("| --- | ---: | ---: | ---: | ---: |");
}
for (const name of scenes) {
  const shipped = new URL(`../scenes/${name}.json`, import.meta.url);
  const generated = new URL(`../target/scenes/${name}.json`, import.meta.url);
  const scene = JSON.parse(readFileSync(existsSync(shipped) ? shipped : generated));
  const runs = Array.from({ length: starts }, (_, k) => layout(scene, k));
  const pairwise = (count, x) => (count <= 3000 ? x : "-");
  if (starts === 1) {
    const m = runs[0];
    console.log(`| ${name} | ${m.ticks} | ${m.cv.toFixed(2)} | ${m.mean.toFixed(0)} | ${m.overlaps} | ${pairwise(m.links.length, m.crossings)} | ${m.ms.toFixed(2)} |`);
  } else {
    const cvs = runs.map((r) => r.cv);
    const mean = cvs.reduce((a, b) => a + b, 0) / cvs.length;
    const overlaps = runs.reduce((a, r) => a + r.overlaps, 0);
    console.log(`| ${name} | ${starts} | ${mean.toFixed(3)} | ${Math.min(...cvs).toFixed(3)}-${Math.max(...cvs).toFixed(3)} | ${overlaps} |`);
  }
}
