// The armgals live view: reads the run's server-sent events (start, loop, frame, end) and draws
// them. No build step, nothing from the internet.
"use strict";
const NS = "http://www.w3.org/2000/svg";
const $ = (id) => document.getElementById(id);
let start = null;
let box = null; // the world's frame: [xmin, xmax, ymin, ymax, zmax], only ever grown
const energies = [];
let loopCount = 0;
const LOOP_ROWS = 200;

function el(name, attrs, parent) {
  const e = document.createElementNS(NS, name);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}

function grow(x, y, z) {
  const m = 0.15;
  if (!box) box = [x - m, x + m, y - m, y + m, z + m];
  box[0] = Math.min(box[0], x - m);
  box[1] = Math.max(box[1], x + m);
  box[2] = Math.min(box[2], y - m);
  box[3] = Math.max(box[3], y + m);
  box[4] = Math.max(box[4], z + m);
}

// A view's scale: the same on both axes, fitting [u0,u1] x [v0,v1] into w x h.
function fit(u0, u1, v0, v1, w, h) {
  const pad = 24;
  const s = Math.min((w - 2 * pad) / (u1 - u0), (h - 2 * pad) / (v1 - v0));
  const ou = pad + ((w - 2 * pad) - s * (u1 - u0)) / 2;
  const ov = pad + ((h - 2 * pad) - s * (v1 - v0)) / 2;
  return { u: (u) => ou + s * (u - u0), v: (v) => h - ov - s * (v - v0), s: s };
}

function ticks(svg, f, u0, u1, v0, v1, w, h, uName, vName) {
  el("line", { x1: f.u(u0), y1: f.v(v0), x2: f.u(u1), y2: f.v(v0), class: "axis" }, svg);
  el("line", { x1: f.u(u0), y1: f.v(v0), x2: f.u(u0), y2: f.v(v1), class: "axis" }, svg);
  const t1 = el("text", { x: f.u(u1) - 40, y: f.v(v0) + 12, class: "tick" }, svg);
  t1.textContent = uName + " " + u1.toFixed(2) + " m";
  const t0 = el("text", { x: f.u(u0), y: f.v(v0) + 12, class: "tick" }, svg);
  t0.textContent = u0.toFixed(2);
  const tv = el("text", { x: 2, y: f.v(v1) + 4, class: "tick" }, svg);
  tv.textContent = vName + " " + v1.toFixed(2);
}

function drawScene(svg, f, side) {
  if (side) {
    el("rect", { x: 0, y: f.v(0), width: 480, height: 200 - f.v(0), class: "ground" }, svg);
  }
  for (const o of start.obstacles) {
    if (o.type === "box") {
      const [cx, cy, cz] = o.c, [sx, sy, sz] = o.size;
      const v0 = side ? cz - sz / 2 : cy - sy / 2, v1 = side ? cz + sz / 2 : cy + sy / 2;
      el("rect", { x: f.u(cx - sx / 2), y: f.v(v1), width: f.s * sx, height: f.s * (v1 - v0), class: "obstacle" }, svg);
    } else if (o.type === "pipe") {
      const [cx, cy, cz] = o.c, r = o.inner + o.wall, l = o.length;
      const along = o.axis === "x" ? [l, 2 * r, 2 * r] : o.axis === "y" ? [2 * r, l, 2 * r] : [2 * r, 2 * r, l];
      const v = side ? [cz, along[2]] : [cy, along[1]];
      el("rect", { x: f.u(cx - along[0] / 2), y: f.v(v[0] + v[1] / 2), width: f.s * along[0], height: f.s * v[1], class: "obstacle", "fill-opacity": 0.5 }, svg);
    }
  }
}

function drawMolecule(svg, frame, side) {
  const w = 480, h = side ? 200 : 300;
  svg.replaceChildren();
  const f = side ? fit(box[0], box[1], 0, box[4], w, h) : fit(box[0], box[1], box[2], box[3], w, h);
  drawScene(svg, f, side);
  ticks(svg, f, box[0], box[1], side ? 0 : box[2], side ? box[4] : box[3], w, h, "x", side ? "z" : "y");
  const atoms = [...frame.atoms].sort((a, b) => side ? b.c[1] - a.c[1] : a.c[2] - b.c[2]);
  for (const a of atoms) {
    const g = el("g", { class: "atom", "data-id": a.id }, svg);
    const cu = f.u(a.c[0]), cv = f.v(side ? a.c[2] : a.c[1]);
    for (const leg of a.legs) {
      el("line", { x1: cu, y1: cv, x2: f.u(leg[0]), y2: f.v(side ? leg[2] : leg[1]), class: leg[3] ? "leg bound" : "leg" }, g);
    }
    el("circle", { cx: cu, cy: cv, r: Math.max(2, f.s * start.kernelRadius), class: "kernel" }, g);
  }
}

function drawEnergy() {
  const svg = $("energy-plot");
  svg.replaceChildren();
  if (energies.length < 2) return;
  const t1 = Math.max(energies[energies.length - 1][0], 1e-9);
  let e1 = 0;
  for (const [, e] of energies) e1 = Math.max(e1, e);
  const f = { u: (t) => 30 + 440 * t / t1, v: (e) => 90 - 80 * e / (e1 || 1) };
  el("polyline", { points: energies.map(([t, e]) => f.u(t).toFixed(1) + "," + f.v(e).toFixed(1)).join(" "), class: "line" }, svg);
  el("line", { x1: 30, y1: 90, x2: 470, y2: 90, class: "axis" }, svg);
  const a = el("text", { x: 2, y: 14, class: "tick" }, svg); a.textContent = e1.toFixed(1);
  const b = el("text", { x: 430, y: 99, class: "tick" }, svg); b.textContent = t1.toFixed(2) + " s";
}

function drawPrograms(programs) {
  const div = $("programs");
  const robots = Object.keys(programs || {});
  if (robots.length === 0) return;
  div.replaceChildren();
  for (const r of robots) {
    const p = programs[r];
    const d = document.createElement("div");
    d.className = "program";
    d.innerHTML = "<b></b> schemas: <span></span><br>schedule:<ol></ol>";
    d.querySelector("b").textContent = r;
    d.querySelector("span").textContent = p.schemas.join(", ");
    const ol = d.querySelector("ol");
    for (const m of p.schedule) { const li = document.createElement("li"); li.textContent = m; ol.appendChild(li); }
    div.appendChild(d);
  }
}

function drawModels(models) {
  const robots = Object.keys(models || {});
  if (robots.length === 0) {
    if (start && start.mode === "view") $("models").innerHTML = "<p class=none>a trace holds no model: the loop below shows what the meta received and asked for</p>";
    return;
  }
  const div = $("models");
  div.replaceChildren();
  for (const r of robots) {
    const box = document.createElement("div");
    box.className = "model";
    const title = document.createElement("b"); title.textContent = "of " + r; box.appendChild(title);
    const d = document.createElement("dl");
    box.appendChild(d);
    for (const [k, v] of Object.entries(models[r])) {
      const dt = document.createElement("dt"); dt.textContent = k;
      const dd = document.createElement("dd"); dd.textContent = String(v); dd.title = String(v);
      d.append(dt, dd);
    }
    div.appendChild(box);
  }
}

function addLoop(records) {
  const body = $("loop").tBodies[0];
  for (const r of records) {
    loopCount++;
    const tr = document.createElement("tr");
    tr.className = r.meta ? "meta" : (r.event === "applied" ? "applied" : r.event === "refused" ? "refused" : "");
    const what = [];
    for (const k of ["kind", "passed", "selector", "request", "reason", "held", "refusal", "text", "version"]) {
      if (r[k] !== undefined) what.push(k === "request" || k === "text" ? r[k] : k + " " + r[k]);
    }
    for (const c of [r.cycle, r.meta ? "meta " + r.meta : "robot", r.event, r.robot, what.join(" · ")]) {
      const td = document.createElement("td"); td.textContent = String(c); tr.appendChild(td);
    }
    body.insertBefore(tr, body.firstChild);
  }
  while (body.rows.length > LOOP_ROWS) body.deleteRow(body.rows.length - 1);
  $("loop-count").textContent = loopCount + " records, the latest first" + (loopCount > LOOP_ROWS ? " (the last " + LOOP_ROWS + " shown)" : "");
}

const events = new EventSource("events");
events.addEventListener("start", (e) => {
  start = JSON.parse(e.data);
  box = null;
  energies.length = 0;
  $("example").textContent = start.example;
  $("scene").textContent = "scene " + start.scene + (start.mode === "view" ? " · played back" : " · live, " + start.speed + "× real time");
  $("cycles").textContent = start.cycles;
  $("state").textContent = start.mode === "view" ? "playing" : "running";
  $("controls").hidden = start.mode !== "view";
  for (const o of start.obstacles) {
    const [cx, cy, cz] = o.c;
    const s = o.size || [o.length, 2 * (o.inner + o.wall), 2 * (o.inner + o.wall)];
    grow(cx - s[0] / 2, cy - s[1] / 2, cz + s[2] / 2);
    grow(cx + s[0] / 2, cy + s[1] / 2, cz + s[2] / 2);
  }
});
events.addEventListener("frame", (e) => {
  const frame = JSON.parse(e.data);
  for (const a of frame.atoms) {
    grow(a.c[0], a.c[1], a.c[2]);
    for (const l of a.legs) grow(l[0], l[1], l[2]);
  }
  $("cycle").textContent = frame.cycle;
  $("time").textContent = frame.t.toFixed(2);
  $("energy").textContent = frame.energy.toFixed(2);
  if (energies.length === 0 || frame.t > energies[energies.length - 1][0]) energies.push([frame.t, frame.energy]);
  drawMolecule($("top"), frame, false);
  drawMolecule($("side"), frame, true);
  drawEnergy();
  drawPrograms(frame.programs);
  drawModels(frame.models);
});
events.addEventListener("loop", (e) => addLoop(JSON.parse(e.data)));
events.addEventListener("end", (e) => {
  const end = JSON.parse(e.data);
  $("state").textContent = end.ran < end.of ? "interrupted after " + end.ran + " cycles" : "ended";
});
events.onerror = () => {
  if (events.readyState === EventSource.CLOSED || $("state").textContent !== "ended") {
    if ($("state").textContent.indexOf("ended") < 0) $("state").textContent = "disconnected";
  }
  if ($("state").textContent === "ended") events.close();
};
for (const c of ["pause", "play", "step", "faster", "slower"]) {
  $(c).addEventListener("click", () => fetch("control?do=" + c, { method: "POST" }));
}
