"use strict";
// The stick lab's page: sliders -> POST /api/run (the CLI's validation and simulator)
// -> animation, numbers, timeline, stroboscope, tasks; POST /api/map -> the (theta_0, mu)
// speed map. The drawing is in page-draw.js; assets.rs joins the two and calls start().

// The sliders (and their order, ends, scales, symbols and defaults) come from the flag
// table: /api/scenes `controls` (src/flags, `Flag::shown_in_lab`); filled in start().
// A control: `log` a logarithmic slider from `lo` (with `zero`: a stop at 0 at its left
// end); `own` the lab's own ends; `rod` chapter 8's rod mass.
let PARAMS = [];
const LOG_STEPS = 1000; // positions of a logarithmic slider (0.3 % of a decade each at 3 decades)
const ZERO_STOP = 25; // positions of the stop at 0 left of a logarithmic slider
// request field -> flag as typed (from the controls, plus the menus); filled in start()
const FLAG_OF = { method: "--method", scene: "--scene" };
// the book's mode colours (chapter 6's gait::mode_colour, the Okabe-Ito palette of
// src/plot), replaced at start-up by /api/scenes `mode_colours`, the one source
const MODES = {
  F: { name: "flight", color: "#0072b2" },
  P: { name: "pivot (C jammed)", color: "#d55e00" },
  L: { name: "slide left", color: "#009e73" },
  R: { name: "slide right", color: "#cc79a7" },
};
const MODE_NAMES = { F: "flight", P: "pivot", L: "slide_left", R: "slide_right" };
const FORCE = "#b3261e"; // the contact force, as in the book's model figure
const CONE = "#2e7d32";
const $ = (id) => document.getElementById(id);

const lab = {
  scene: "jamming", values: {}, scenes: null, run: null, cmp: null, map: null,
  seq: 0, inFlight: false, pending: false, inputStamp: null, latencies: [], timings: [],
  simT: 0, frame: 0, frameCount: 0, playing: true, lastWall: null, mapSeq: 0, mapTimer: null,
  history: [], tasks: {}, draw: {},
};
window.__lab = lab; // read by the browser test

// ---------- numbers as a reader types them ----------
function fmt(x, digits) {
  if (!Number.isFinite(x)) return "-";
  if (x === 0) return "0";
  return Number(x.toPrecision(digits)).toString();
}
const pct = (x) => `${(100 * x).toFixed(1)} %`;
// a slider's value as text: the step's decimals (linear) or 3 significant digits (log)
function sliderText(p, v) {
  if (p.log) return v === 0 ? "0" : fmt(v, 3);
  const dec = Math.max(0, -Math.floor(Math.log10(p.step) + 1e-9));
  return String(Number((Math.round(v / p.step) * p.step).toFixed(dec)));
}

// ---------- controls ----------
function logEnds(p) { return [Math.max(p.min, p.lo || p.min), p.max]; }
function toPos(p, v) {
  if (!p.log) return v;
  const [lo, hi] = logEnds(p);
  if (p.zero && v <= 0) return -ZERO_STOP;
  return Math.round((LOG_STEPS * Math.log(Math.max(v, lo) / lo)) / Math.log(hi / lo));
}
function fromPos(p, pos) {
  if (!p.log) return Number(pos);
  const [lo, hi] = logEnds(p);
  if (pos < 0) return 0;
  return lo * Math.pow(hi / lo, pos / LOG_STEPS); // formula: v = lo (hi/lo)^(pos/N)
}

function buildSliders() {
  const box = $("sliders");
  for (const p of PARAMS) {
    const div = document.createElement("div");
    div.className = p.rod ? "param ch8" : "param";
    const [mn, mx, st] = p.log ? [p.zero ? -ZERO_STOP : 0, LOG_STEPS, 1] : [p.min, p.max, p.step];
    div.innerHTML = `<div class="top"><label for="f-${p.key}"><span class="name">${p.name}</span>` +
      `<span class="unit">${p.unit}</span>${p.log ? '<span class="scale">log scale</span>' : ""}</label>` +
      `<input type="text" inputmode="decimal" id="f-${p.key}" aria-label="${p.name} value"></div>` +
      `<input type="range" id="s-${p.key}" min="${mn}" max="${mx}" step="${st}" aria-label="${p.name}">` +
      `<div class="help">${p.help}</div>`;
    box.appendChild(div);
    div.querySelector(`#s-${p.key}`).title = p.title;
    const field = div.querySelector(`#f-${p.key}`);
    const slider = div.querySelector(`#s-${p.key}`);
    slider.addEventListener("input", () => {
      const text = sliderText(p, fromPos(p, Number(slider.value)));
      field.value = text;
      setValue(p.key, text);
    });
    field.addEventListener("change", () => {
      const v = field.value.trim();
      if (v !== "" && Number.isFinite(Number(v))) slider.value = toPos(p, Number(v));
      setValue(p.key, v);
    });
  }
}

// The page's controls from the flag table: the sliders, and the menus (rtol's values,
// the integrators); an open end stays one step inside.
function controlsFromTable(controls, choices) {
  PARAMS = [];
  for (const c of controls) {
    FLAG_OF[c.key] = c.flag;
    if (c.scale === "menu") {
      $(c.key).innerHTML = c.values.map((v) => `<option>${v.toExponential()}</option>`).join("");
      $(c.key).title = `${c.range} (${c.unit || "1"}): ${c.reason}`;
      continue;
    }
    const p = { key: c.key, name: c.name, unit: c.unit, help: c.help, log: c.scale === "log", own: c.own, rod: c.rod };
    if (p.log) {
      p.lo = c.lo; p.zero = c.zero;
      p.min = c.min_open ? c.min * 1.001 : c.min;
      p.max = c.max_open ? c.max * 0.999 : c.max;
    } else {
      p.step = c.step;
      p.min = c.min_open ? c.min + c.step : c.min;
      p.max = c.max_open ? c.max - c.step : c.max;
    }
    p.title = `${c.range} (${c.unit || "1"}): ${c.reason}`;
    p.default = c.default;
    PARAMS.push(p);
  }
  $("method").innerHTML = choices.method.map((m) => `<option value="${m.name}">${m.about.split(":")[0]}</option>`).join("");
}

function setValue(key, text) {
  lab.values[key] = String(text);
  if (!["theta0_rad", "mu", "duration_s", "rod_mass_kg"].includes(key)) scheduleMap();
  markPreset();
  changed();
}

function showValues() {
  for (const p of PARAMS) {
    const v = lab.values[p.key];
    $(`f-${p.key}`).value = v;
    $(`s-${p.key}`).value = toPos(p, Number(v));
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
  const b = body();
  try {
    const { ok, j } = await post("/api/run", b);
    const answered = performance.now();
    if (!ok) showError(j.error);
    else if (j.seq === lab.seq) { hideError(); lab.runBody = b; applyRun(j, stamp, answered); }
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
// The run the animation shows: chapter 8's rod when it has a mass, chapter 6's otherwise.
function shown(run) { return run.rod ? run.rod : run; }

function applyRun(j, stamp, answered) {
  const old = lab.run;
  lab.run = j;
  const fr = shown(j).frames;
  lab.frameCount = fr.t_s.length;
  const tEnd = fr.t_s[fr.t_s.length - 1] || 0;
  if (!old || lab.simT > tEnd) lab.simT = 0;
  showNumbers(j);
  drawEnergy(j.report.results.energy_budget_j);
  drawTimeline();
  drawStrobe();
  drawMap();
  recordRun(j);
  checkTasks();
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

// The time fractions of each mode and the highest hop of C above the plate (m), from
// the frames.
function frameStats(fr) {
  const n = fr.t_s.length, count = { F: 0, P: 0, L: 0, R: 0 };
  let hop = 0;
  for (let i = 0; i < n; i++) {
    count[fr.mode[i]] = (count[fr.mode[i]] || 0) + 1;
    if (fr.mode[i] === "F") hop = Math.max(hop, fr.z_c_m[i] - fr.plate_z_m[i]);
  }
  const f = (k) => (n ? count[k] / n : 0);
  return { flight: f("F"), pivot: f("P"), sliding: f("L") + f("R"), hop };
}

function showNumbers(j) {
  const r = j.report.results, rod = j.rod;
  const v = rod ? rod.mean_velocity_mps : r.mean_velocity_mps;
  const sv = $("speed-value");
  sv.dataset.mps = v === undefined || v === null ? "" : String(v);
  sv.textContent = v === undefined || v === null ? "-" : `${fmt(v * 1e3, 4)} mm/s`;
  $("speed-label").textContent = rod ? `mean speed of C (rod of ${fmt(rod.rod_mass_kg, 3)} kg, chapter 8)` : "mean speed of C";
  const gl = $("ghost-line");
  gl.hidden = !rod;
  if (rod) {
    const g = rod.ghost.mean_velocity_mps;
    gl.textContent = `ghost, the massless model (all ${fmt(rod.ghost.mass_kg, 3)} kg at P): ${g === null ? "-" : `${fmt(g * 1e3, 4)} mm/s`}, ${rod.ghost.outcome}`;
  }
  const out = $("outcome");
  const outcome = rod ? rod.outcome : r.outcome;
  const reason = rod ? rod.outcome_reason : r.outcome_reason;
  out.textContent = outcome + (reason ? `: ${reason}` : "");
  out.className = `badge ${outcome}`;
  const st = frameStats(shown(j).frames);
  if (rod) {
    $("hops").textContent = rod.impacts;
    $("flight").textContent = pct(st.flight);
    $("pivot").textContent = pct(st.pivot);
    $("sliding").textContent = pct(st.sliding);
  } else {
    const pf = r.phase_fractions;
    $("hops").textContent = r.hops;
    $("flight").textContent = pct(pf.flight);
    $("pivot").textContent = pct(pf.pivot);
    $("sliding").textContent = pct(pf.slide_left + pf.slide_right);
  }
  lab.hopMm = st.hop * 1e3;
  $("hop-height").textContent = st.hop > 0 ? `${fmt(st.hop * 1e3, 3)} mm` : "no flight";
  $("compute").textContent = `${fmt(j.compute_ms, 3)} ms`;
}

function frameAt(frames, t) {
  const ts = frames.t_s;
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

// ---------- guided tasks ----------
// Each task is judged from the numbers of the runs the page received (`lab.history`:
// the parameters and results of each, newest last).
const WALK_MPS = 1e-5; // "walks": |mean speed| at least 0.01 mm/s
const TASKS = [
  {
    id: "backwards", text: "Make it walk backwards (to the left).",
    hint: "hint: what decides the direction it walks? try the lean θ₀",
    check(h) {
      const r = h.find((x) => x.outcome === "completed" && x.v < -WALK_MPS);
      return r && `done: ${fmt(r.v * 1e3, 3)} mm/s at θ₀ = ${r.p.theta0_rad}, μ = ${r.p.mu}`;
    },
  },
  {
    id: "onset", text: "Find the Γ where it starts to walk.",
    hint: "hint: lower Γ until the stick stands still, then raise it in small steps (two runs within 10 % of Γ)",
    check(h) {
      for (let i = 0; i < h.length; i++) {
        for (let k = 0; k < h.length; k++) {
          const a = h[i], b = h[k];
          if (a.key !== b.key || !(a.gamma < b.gamma) || b.gamma - a.gamma > 0.1 * b.gamma) continue;
          if (Math.abs(a.v) < WALK_MPS && a.outcome === "completed" && Math.abs(b.v) >= WALK_MPS && b.outcome === "completed") {
            return `done: it starts to walk between Γ = ${a.gamma} and Γ = ${b.gamma}`;
          }
        }
      }
      return null;
    },
  },
  {
    id: "unstable", text: "Start from a stable gait and make it lose stability.",
    hint: "hint: watch the stroboscope; change one slider until |λ| passes 1 (or the gait repeats only every 2 cycles)",
    check(h) {
      const lost = (x) => x.outcome === "completed" && x.fixed && (x.fixed.period > 1 || x.fixed.leading_modulus > 1);
      const stable = (x) => x.outcome === "completed" && x.fixed && x.fixed.period === 1 && x.fixed.stable;
      for (let k = 1; k < h.length; k++) {
        if (!lost(h[k])) continue;
        const from = h.slice(0, k).find((x) => stable(x) && oneChange(x.p, h[k].p));
        if (!from) continue;
        const key = oneChange(from.p, h[k].p);
        const what = (PARAMS.find((p) => p.key === key) || { name: key }).name;
        return h[k].fixed.period > 1
          ? `done: ${what} ${from.p[key]} → ${h[k].p[key]} leaves only a period-${h[k].fixed.period} gait`
          : `done: ${what} ${from.p[key]} → ${h[k].p[key]}: |λ| ${fmt(from.fixed.leading_modulus, 3)} → ${fmt(h[k].fixed.leading_modulus, 3)} > 1`;
      }
      return null;
    },
  },
];

// The one parameter in which two runs' parameters differ (the duration aside), or null.
function oneChange(a, b) {
  const diff = Object.keys(a).filter((k) => k !== "duration_s" && a[k] !== b[k]);
  return diff.length === 1 ? diff[0] : null;
}

// The run's parameters as the reader typed them (`lab.runBody`, not the report's
// values recomputed from the plate, as Gamma = delta omega^2/g = 0.6000000000000001).
function recordRun(j) {
  const { seq, ...p } = lab.runBody;
  const r = j.report.results;
  const rod = j.rod;
  const others = { ...p, gamma: null, duration_s: null };
  lab.history.push({
    p, gamma: Number(p.gamma), key: JSON.stringify(others),
    v: rod ? rod.mean_velocity_mps : r.mean_velocity_mps,
    outcome: rod ? rod.outcome : r.outcome,
    fixed: rod ? null : j.cycle.fixed,
  });
  if (lab.history.length > 200) lab.history.shift();
}

function buildTasks() {
  $("task-list").innerHTML = TASKS.map((t) => `<li id="task-${t.id}">${t.text}<span class="state">${t.hint}</span></li>`).join("");
}

function checkTasks() {
  for (const t of TASKS) {
    if (lab.tasks[t.id]) continue;
    const done = t.check(lab.history);
    if (!done) continue;
    lab.tasks[t.id] = done;
    const li = $(`task-${t.id}`);
    li.classList.add("done");
    li.querySelector(".state").textContent = `✓ ${done}`;
  }
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

// The trajectory of the shown run, one frame a line, SI units.
function trajectoryCsv(run) {
  const f = shown(run).frames;
  const lines = ["t_s,theta_rad,x_c_m,z_c_m,z_s_m,f_x_n,f_z_n,mode"];
  for (let i = 0; i < f.t_s.length; i++) {
    lines.push([f.t_s[i], f.theta_rad[i], f.x_c_m[i], f.z_c_m[i], f.plate_z_m[i], f.f_x_n[i], f.f_z_n[i], MODE_NAMES[f.mode[i]]].join(","));
  }
  return `${lines.join("\n")}\n`;
}

function summaryJson(run) {
  if (!run.rod) return `${run.report_text}\n`;
  const { frames, ghost, ...rod } = run.rod;
  const g = { ...ghost };
  delete g.frames;
  return `${JSON.stringify({ ...run.report, rod: { ...rod, ghost: g } })}\n`;
}

// ---------- start ----------
function legend() {
  $("legend").innerHTML = Object.values(MODES).map((m) => `<span><i style="background:${m.color}"></i>${m.name}</span>`).join("") +
    `<span><i style="background:${FORCE}"></i>contact force F on C</span><span><i style="background:rgba(46,125,50,0.3)"></i>friction cone</span>`;
}

function applyPalette(c) {
  if (!c) return;
  for (const k of Object.keys(MODES)) if (c[k]) MODES[k].color = c[k].hex;
}

async function start() {
  buildTasks();
  try {
    lab.scenes = await (await fetch("/api/scenes")).json();
    controlsFromTable(lab.scenes.controls, lab.scenes.choices);
    applyPalette(lab.scenes.mode_colours);
  } catch (e) {
    showError(`the lab does not answer: is \`workbook lab\` still running? (${e.message})`);
    return;
  }
  buildSliders();
  legend();
  lab.values.method = lab.scenes.choices.method[0].name;
  lab.values.rtol = String(lab.scenes.controls.find((c) => c.key === "rtol").default);
  lab.values.duration_s = "2";
  lab.values.rod_mass_kg = "0";
  readUrl();
  showValues();
  wire();
  fitCanvases();
  window.addEventListener("resize", fitCanvases);
  sendMap();
  changed();
  requestAnimationFrame(tick);
}

function wire() {
  for (const b of document.querySelectorAll(".preset")) {
    b.addEventListener("click", () => { loadScene(b.dataset.scene); showValues(); scheduleMap(); changed(); });
  }
  $("method").addEventListener("change", () => setValue("method", $("method").value));
  $("rtol").addEventListener("change", () => setValue("rtol", $("rtol").value));
  $("play").addEventListener("click", togglePlay);
  $("step").addEventListener("click", () => {
    lab.playing = false; $("play").textContent = "Play";
    const ts = lab.run ? shown(lab.run).frames.t_s : [];
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
  $("keep").addEventListener("click", () => { if (lab.run) { lab.cmp = lab.run; $("clear-compare").disabled = false; drawTimeline(); } });
  $("clear-compare").addEventListener("click", () => { lab.cmp = null; $("clear-compare").disabled = true; drawTimeline(); });
  $("dl-traj").addEventListener("click", () => lab.run && download("stick-trajectory.csv", trajectoryCsv(lab.run), "text/csv"));
  $("dl-csv").addEventListener("click", () => lab.run && download("stick-switches.csv", lab.run.events_csv, "text/csv"));
  $("dl-json").addEventListener("click", () => lab.run && download("stick-run.json", summaryJson(lab.run), "application/json"));
}

function togglePlay() {
  lab.playing = !lab.playing;
  $("play").textContent = lab.playing ? "Pause" : "Play";
}
