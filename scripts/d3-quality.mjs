// d3-force v3 on the shipped scenes: link distance 100, default many-body, collide at the
// node radius, centre. Prints edge-length CV, overlapping pairs, crossings, ticks to
// settle (d3 stops when alpha < alphaMin: 300 ticks) and the mean tick time.
//
//   cd scripts && npm install && node d3-quality.mjs [scene ...]
import { readFileSync } from "node:fs";
import { forceSimulation, forceLink, forceManyBody, forceCollide, forceCenter } from "d3-force";

const scenes = process.argv.length > 2 ? process.argv.slice(2)
  : ["karate", "les_miserables", "florentine", "n200_e500", "tree_1023", "grid_30x30", "n1000_e2500", "n10000_e25000"];

function measure(nodes, links) {
  const lengths = links.map((l) => Math.hypot(l.source.x - l.target.x, l.source.y - l.target.y));
  const mean = lengths.reduce((a, b) => a + b, 0) / lengths.length;
  const sd = Math.sqrt(lengths.reduce((a, l) => a + (l - mean) ** 2, 0) / lengths.length);
  let overlaps = 0;
  if (nodes.length <= 3000) {
    for (let i = 0; i < nodes.length; i++)
      for (let j = i + 1; j < nodes.length; j++)
        if (Math.hypot(nodes[i].x - nodes[j].x, nodes[i].y - nodes[j].y) - nodes[i].radius - nodes[j].radius < -0.5) overlaps++;
  }
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

console.log("| scene | ticks | edge-length CV | mean edge | overlaps | crossings | ms per tick |");
console.log("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
for (const name of scenes) {
  const scene = JSON.parse(readFileSync(new URL(`../scenes/${name}.json`, import.meta.url)));
  const nodes = scene.nodes.map((n) => ({ id: n.id, x: n.x, y: n.y, radius: n.radius || 16 }));
  const links = scene.edges.filter(([a, b]) => a !== b).map(([source, target]) => ({ source, target }));
  const sim = forceSimulation(nodes)
    .force("link", forceLink(links).id((d) => d.id).distance(100))
    .force("charge", forceManyBody())
    .force("collide", forceCollide((d) => d.radius))
    .force("center", forceCenter(0, 0))
    .stop();
  let ticks = 0;
  const started = process.hrtime.bigint();
  while (sim.alpha() >= sim.alphaMin()) { sim.tick(); ticks++; }
  const ms = Number(process.hrtime.bigint() - started) / 1e6 / ticks;
  const m = measure(nodes, links);
  const fmt = (x) => (x === undefined ? "-" : x);
  console.log(`| ${name} | ${ticks} | ${m.cv.toFixed(2)} | ${m.mean.toFixed(0)} | ${nodes.length <= 3000 ? m.overlaps : "-"} | ${links.length <= 3000 ? m.crossings : "-"} | ${ms.toFixed(2)} |`);
}
