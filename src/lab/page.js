"use strict";
// The stick lab's page: sliders -> POST /api/run (the CLI's validation and simulator)
// -> animation, numbers, timeline; POST /api/map -> the (theta_0, mu) speed map.
// The drawing is in page-draw.js; assets.rs joins the two and calls start().

const PARAMS = [
  { key: "theta0_rad", name: "θ₀", unit: "rad", min: 0, max: 1.5, step: 0.005, help: "spring rest angle from the vertical" },
  { key: "mu", name: "μ", unit: "", min: 0, max: 2, step: 0.01, help: "friction coefficient at the foot C" },
  { key: "gamma", name: "Γ", unit: "", min: 0, max: 50, step: 0.1, help: "peak plate acceleration over g" },
  { key: "frequency_hz", name: "f", unit: "Hz", min: 1, max: 200, step: 1, help: "plate frequency" },
  { key: "stiffness", name: "k", unit: "N m/rad", min: 0, max: 100, step: 0.5, help: "hinge spring" },
  { key: "damping", name: "γ", unit: "N m s/rad", min: 0, max: 0.1, step: 0.0005, help: "hinge damper" },
  { key: "length_m", name: "L", unit: "m", min: 0.015, max: 1.5, step: 0.005, help: "rod length" },
  { key: "mass_kg", name: "m", unit: "kg", min: 0.1, max: 10, step: 0.1, help: "tip mass at P" },
  { key: "duration_s", name: "duration", unit: "s", min: 0.2, max: 10, step: 0.1, help: "simulated time", own: true },
];
// min and max above are the fallback: the sliders' ends come from chapter 6's flag table
// (/api/scenes `ranges`, the CLI's ranges), except where the lab has its own bound
// (`own`: the duration, bounded by the lab's 1000 drive cycles).
const FLAG_OF = {
  theta0_rad: "--theta0-rad", mu: "--mu", gamma: "--gamma", frequency_hz: "--frequency-hz",
  stiffness: "--stiffness", damping: "--damping", length_m: "--length-m", mass_kg: "--mass-kg",
  duration_s: "--duration-s", rtol: "--rtol", method: "--method", scene: "--scene",
};
const MAP_KEYS = ["scene", "gamma", "frequency_hz", "stiffness", "damping", "length_m", "mass_kg", "method", "rtol"];
const MODES = {
  F: { name: "flight", color: "#3182ce" },
  P: { name: "pivot (C stuck)", color: "#2f855a" },
  L: { name: "slide left", color: "#dd6b20" },
  R: { name: "slide right", color: "#805ad5" },
};
const $ = (id) => document.getElementById(id);

const lab = {
  scene: "jamming", values: {}, scenes: null, run: null, cmp: null, map: null,
  seq: 0, inFlight: false, pending: false, inputStamp: null, latencies: [], timings: [],
  simT: 0, frame: 0, frameCount: 0, playing: true, lastWall: null, mapSeq: 0, mapTimer: null,
};
window.__lab = lab; // read by the browser test

// ---------- controls ----------
function buildSliders() {
  const box = $("sliders");
  for (const p of PARAMS) {
    const div = document.createElement("div");
    div.className = "param";
    div.innerHTML = `<div class="top"><label for="f-${p.key}"><span class="name">${p.name}</span>` +
      `<span class="unit">${p.unit}</span></label>` +
      `<input type="text" inputmode="decimal" id="f-${p.key}" aria-label="${p.name} value"></div>` +
      `<input type="range" id="s-${p.key}" min="${p.min}" max="${p.max}" step="${p.step}" aria-label="${p.name}">` +
      `<div class="help">${p.help}</div>`;
    box.appendChild(div);
    const field = div.querySelector(`#f-${p.key}`);
    const slider = div.querySelector(`#s-${p.key}`);
    slider.addEventListener("input", () => {
      field.value = slider.value;
      setValue(p.key, slider.value);
    });
    field.addEventListener("change", () => {
      const v = field.value.trim();
      if (v !== "" && Number.isFinite(Number(v))) slider.value = v;
      setValue(p.key, v);
    });
  }
}

// The sliders' ends from the flag table; an open end stays one step inside.
function applyRanges(ranges) {
  for (const p of PARAMS) {
    const r = ranges && ranges[p.key];
    if (!r || p.own) continue;
    const s = $(`s-${p.key}`);
    s.min = r.min_open ? r.min + p.step : r.min;
    s.max = r.max_open ? r.max - p.step : r.max;
    s.title = `${r.range} (${r.unit}): ${r.reason}`;
  }
}

function setValue(key, text) {
  lab.values[key] = String(text);
  if (key !== "theta0_rad" && key !== "mu" && key !== "duration_s") scheduleMap();
  markPreset();
  changed();
}

function showValues() {
  for (const p of PARAMS) {
    const v = lab.values[p.key];
    $(`f-${p.key}`).value = v;
    $(`s-${p.key}`).value = v;
  }
  $("method").value = lab.values.method;
  $("rtol").value = lab.values.rtol;
}

function loadScene(name, keep) {
  lab.scene = name;
  const s = lab.scenes[name];
  for (const p of PARAMS) {
    if (p.key in s && !(keep && p.key in keep)) lab.values[p.key] = String(s[p.key]);
  }
  markPreset();
}

function markPreset() {
  for (const b of document.querySelectorAll(".preset")) {
    const s = lab.scenes && lab.scenes[b.dataset.scene];
    const same = s && b.dataset.scene === lab.scene &&
      PARAMS.every((p) => !(p.key in s) || Number(lab.values[p.key]) === s[p.key]);
    b.classList.toggle("active", !!same);
  }
}

function body() {
  const b = { seq: lab.seq, scene: lab.scene };
  for (const p of PARAMS) b[p.key] = lab.values[p.key];
  b.method = lab.values.method;
  b.rtol = lab.values.rtol;
  return b;
}

function changed() {
  if (lab.inputStamp === null) lab.inputStamp = performance.now();
  writeUrl();
  lab.pending = true;
  if (!lab.inFlight) sendRun();
}

// The address bar carries the parameters (a link reproduces the run); written at most
// every 300 ms, since browsers limit history.replaceState (Safari: 100 calls in 30 s).
function writeUrl() {
  if (lab.urlTimer) return;
  lab.urlTimer = setTimeout(() => {
    lab.urlTimer = null;
    try { history.replaceState(null, "", `?${query()}`); } catch (e) { /* the address bar is a convenience */ }
  }, 300);
}

function query() {
  const q = new URLSearchParams();
  q.set("scene", lab.scene);
  for (const p of PARAMS) q.set(p.key, lab.values[p.key]);
  q.set("method", lab.values.method);
  q.set("rtol", lab.values.rtol);
  return q;
}

function readUrl() {
  const q = new URLSearchParams(location.search);
  const scene = q.get("scene");
  loadScene(scene === "authors" ? "authors" : "jamming");
  for (const k of [...PARAMS.map((p) => p.key), "method", "rtol"]) {
    if (q.has(k)) lab.values[k] = q.get(k);
  }
}

// ---------- server ----------
async function post(path, b) {
  const r = await fetch(path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(b) });
  let j;
  try { j = await r.json(); } catch (e) { j = { error: `the lab answered ${r.status} without JSON` }; }
  return { ok: r.ok, j };
}

async function sendRun() {
  lab.pending = false;
  lab.inFlight = true;
  lab.seq += 1;
  const stamp = lab.inputStamp;
  lab.inputStamp = null;
  try {
    const { ok, j } = await post("/api/run", body());
    const answered = performance.now();
    if (!ok) showError(j.error);
    else if (j.seq === lab.seq) { hideError(); applyRun(j, stamp, answered); }
  } catch (e) {
    showError(`the lab does not answer: is \`workbook lab\` still running? (${e.message})`);
  }
  lab.inFlight = false;
  if (lab.pending) sendRun();
}

function showError(text) {
  const box = $("error");
  box.textContent = text;
  box.hidden = false;
  for (const el of document.querySelectorAll(".param input")) el.classList.remove("bad");
  const m = /for (--[a-z0-9-]+)/.exec(text) || /'(--[a-z0-9-]+)/.exec(text);
  if (m) {
    const key = Object.keys(FLAG_OF).find((k) => FLAG_OF[k] === m[1]);
    if (key && $(`f-${key}`)) $(`f-${key}`).classList.add("bad");
  }
  $("stage").classList.add("stale");
  $("numbers").classList.add("stale");
}

function hideError() {
  $("error").hidden = true;
  for (const el of document.querySelectorAll(".param input")) el.classList.remove("bad");
  $("stage").classList.remove("stale");
  $("numbers").classList.remove("stale");
}

function scheduleMap() {
  clearTimeout(lab.mapTimer);
  lab.mapTimer = setTimeout(sendMap, 250);
}

async function sendMap() {
  const my = ++lab.mapSeq;
  $("map-status").textContent = "computing...";
  try {
    const { ok, j } = await post("/api/map", { ...body(), seq: my });
    if (my !== lab.mapSeq) return;
    if (ok) { lab.map = j; $("map-status").textContent = `(${Math.round(j.compute_ms)} ms)`; }
    else $("map-status").textContent = "(no map: a value is out of range)";
  } catch (e) {
    $("map-status").textContent = "(no answer)";
  }
  drawMap();
}

// ---------- a run ----------
function applyRun(j, stamp, answered) {
  const old = lab.run;
  lab.run = j;
  const fr = j.frames;
  lab.frameCount = fr.t_s.length;
  const tEnd = fr.t_s[fr.t_s.length - 1] || 0;
  if (!old || lab.simT > tEnd) lab.simT = 0;
  const r = j.report.results;
  const v = r.mean_velocity_mps;
  const sv = $("speed-value");
  sv.dataset.mps = v === undefined ? "" : String(v);
  sv.textContent = v === undefined ? "-" : `${fmt(v * 1e3, 4)} mm/s`;
  const out = $("outcome");
  out.textContent = r.outcome + (r.outcome_reason ? `: ${r.outcome_reason}` : "");
  out.className = `badge ${r.outcome}`;
  const pf = r.phase_fractions;
  $("hops").textContent = r.hops;
  $("flight").textContent = pct(pf.flight);
  $("pivot").textContent = pct(pf.pivot);
  $("sliding").textContent = pct(pf.slide_left + pf.slide_right);
  $("compute").textContent = `${fmt(j.compute_ms, 3)} ms`;
  drawEnergy(r.energy_budget_j);
  drawTimeline();
  drawMap();
  if (stamp !== null) {
    const applied = performance.now();
    requestAnimationFrame(() => {
      const now = performance.now();
      lab.latencies.push(now - stamp);
      // where the time goes: the answer (server run + transfer + JSON), the page's
      // redraw of numbers, timeline and map, and the wait for the next frame
      lab.timings.push({ answer: answered - stamp, server: j.compute_ms, redraw: applied - answered, frame: now - applied });
    });
  }
}

function fmt(x, digits) {
  if (!Number.isFinite(x)) return "-";
  if (x === 0) return "0";
  return Number(x.toPrecision(digits)).toString();
}
const pct = (x) => `${(100 * x).toFixed(1)} %`;

function frameAt(run, t) {
  const ts = run.frames.t_s;
  let lo = 0, hi = ts.length - 1;
  if (hi < 0) return -1;
  if (t <= ts[0]) return 0;
  if (t >= ts[hi]) return hi;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (ts[mid] <= t) lo = mid; else hi = mid;
  }
  return lo;
}

// ---------- downloads ----------
function download(name, text, type) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
  document.body.appendChild(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
}

// ---------- start ----------
function legend() {
  $("legend").innerHTML = Object.values(MODES).map((m) => `<span><i style="background:${m.color}"></i>${m.name}</span>`).join("") +
    `<span><i style="background:#c53030"></i>contact force on C</span><span><i style="background:rgba(72,187,120,0.4)"></i>friction cone</span>`;
}

async function start() {
  buildSliders();
  legend();
  try {
    lab.scenes = await (await fetch("/api/scenes")).json();
    applyRanges(lab.scenes.ranges);
  } catch (e) {
    showError(`the lab does not answer: is \`workbook lab\` still running? (${e.message})`);
    return;
  }
  lab.values.method = "dop853";
  lab.values.rtol = "1e-10";
  lab.values.duration_s = "2";
  readUrl();
  showValues();
  for (const b of document.querySelectorAll(".preset")) {
    b.addEventListener("click", () => { loadScene(b.dataset.scene); showValues(); scheduleMap(); changed(); });
  }
  $("method").addEventListener("change", () => setValue("method", $("method").value));
  $("rtol").addEventListener("change", () => setValue("rtol", $("rtol").value));
  $("play").addEventListener("click", togglePlay);
  $("step").addEventListener("click", () => {
    lab.playing = false; $("play").textContent = "Play";
    const ts = lab.run ? lab.run.frames.t_s : [];
    if (ts.length) lab.simT = ts[Math.min(ts.length - 1, lab.frame + 1)];
    if (lab.simT >= ts[ts.length - 1]) lab.simT = 0;
  });
  document.addEventListener("keydown", (ev) => { if (ev.code === "Space" && ev.target.tagName !== "INPUT") { ev.preventDefault(); togglePlay(); } });
  $("timeline").addEventListener("click", (ev) => {
    const cv = $("timeline"), rect = cv.getBoundingClientRect();
    const px = ((ev.clientX - rect.left) * cv.width) / rect.width;
    lab.simT = Math.max(0, ((px - TL.left) / (cv.width - TL.left - TL.right)) * (lab.tlEnd || 0));
  });
  $("map").addEventListener("click", mapClick);
  $("map").addEventListener("mousemove", mapHover);
  $("magnify").addEventListener("change", () => {});
  $("keep").addEventListener("click", () => { if (lab.run) { lab.cmp = lab.run; $("clear-compare").disabled = false; drawTimeline(); } });
  $("clear-compare").addEventListener("click", () => { lab.cmp = null; $("clear-compare").disabled = true; drawTimeline(); });
  $("dl-csv").addEventListener("click", () => lab.run && download("stick-events.csv", lab.run.events_csv, "text/csv"));
  $("dl-json").addEventListener("click", () => lab.run && download("stick-run.json", `${lab.run.report_text}\n`, "application/json"));
  sendMap();
  changed();
  requestAnimationFrame(tick);
}

function togglePlay() {
  lab.playing = !lab.playing;
  $("play").textContent = lab.playing ? "Pause" : "Play";
}
