// Browser test of `workbook lab` (issues 23 and 31), in headless Chromium over the
// DevTools protocol (book/cdp.mjs: no npm package needed). Starts the lab on a free
// loopback port, loads the page and checks, failing on any miss:
//   - the page loads nothing from outside the lab (no CDN) and logs no error;
//   - URL query parameters preset the sliders;
//   - a slider moved with the mouse re-runs the simulator, and the displayed mean speed
//     is the CLI's (`workbook stick-state-machine --json` with the same flags);
//   - the animation advances; an out-of-range value shows the CLI's own one-line reason;
//   - a click on the speed map sets theta_0 and mu and runs them;
//   - issue 31: the modes' colours are the book's (read from src/plot and chapter 6's
//     gait.rs), also in the drawn timeline; the contact force is drawn on top of the rod
//     where it lies along it; the foot close-up's millimetre scale reads the hop height;
//     logarithmic sliders and values as typed; nice timeline ticks; the trajectory CSV,
//     switches CSV and summary JSON downloads; the stroboscope's multiplier against the
//     chapter's published one and against the samples' own contraction; the kept run on
//     its own plate; chapter 8's rod with its ghost, against chapter 8's CLI; the three
//     guided tasks; the layout at 400 px.
// Measures the time from a slider's input event to the first animation frame drawn with
// the new run (reported, not asserted). Screenshots (1280 and 400 px wide):
// target/lab-screenshots/*.png.
//
// Usage: node [--experimental-websocket] book/lab-test.mjs <chromium> <workbook binary>
import { spawn, execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { join, resolve } from "node:path";
import { Cdp, launchChromium } from "./cdp.mjs";

const shotDir = resolve("target/lab-screenshots");
const chromiumBin = process.argv[2] || "chromium";
const workbook = resolve(process.argv[3] || "target/debug/workbook");
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

function startLab() {
  const proc = spawn(workbook, ["lab", "--port", "0"], { stdio: ["ignore", "pipe", "pipe"] });
  return new Promise((ok, fail) => {
    let out = "";
    const timer = setTimeout(() => fail(new Error(`the lab did not start:\n${out}`)), 30000);
    const read = (d) => {
      out += d;
      const m = /(http:\/\/127\.0\.0\.1:\d+\/)/.exec(out);
      if (m) { clearTimeout(timer); ok({ proc, url: m[1] }); }
    };
    proc.stdout.on("data", read);
    proc.stderr.on("data", read);
    proc.on("exit", (code) => fail(new Error(`the lab exited (${code}):\n${out}`)));
  });
}

/// The CLI's results for the jamming scene with `flags`, or its stderr line and exit code.
function cli(flags) {
  const args = ["stick-state-machine", "--json", "--no-figures", "--duration-s", "2", ...flags];
  try {
    const out = execFileSync(workbook, args, { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
    return { code: 0, json: JSON.parse(out) };
  } catch (e) {
    return { code: e.status, stderr: String(e.stderr).trim() };
  }
}

/// Chapter 8's CLI (`workbook stick-with-inertia`) for the jamming scene with `flags`.
function cli8(flags) {
  const args = ["stick-with-inertia", "--json", "--no-figures", "--quick", "--duration-s", "2", ...flags];
  try {
    const out = execFileSync(workbook, args, { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
    return { code: 0, json: JSON.parse(out) };
  } catch (e) {
    return { code: e.status, stderr: String(e.stderr).trim() };
  }
}

/// Gamma values of the task "find the Gamma where it starts to walk" (jamming scene):
/// standing still at the first, walking at the second (within 10 %).
const TASK_ONSET = ["0.55", "0.6"];
/// Changes that make the self-locking gait lose stability.
const TASK_UNSTABLE = [["gamma", "8"]];

/// The page's own number format (page.js `fmt`).
const fmt = (x, d) => (x === 0 ? "0" : Number(x.toPrecision(d)).toString());

async function main() {
  rmSync(shotDir, { recursive: true, force: true });
  mkdirSync(shotDir, { recursive: true });
  const lab = await startLab();
  const origin = lab.url.replace(/\/$/, "");
  const { proc, profile, browserUrl } = await launchChromium(chromiumBin, "lab-test-", "1280,1000");
  const failures = [];
  const fail = (m) => { failures.push(m); console.error(`FAIL ${m}`); };
  const okm = (m) => console.log(`ok ${m}`);
  try {
    const cdp = new Cdp(browserUrl);
    await cdp.open();
    const { targetId } = await cdp.send("Target.createTarget", { url: "about:blank" });
    const { sessionId } = await cdp.send("Target.attachToTarget", { targetId, flatten: true });
    const s = (m, p) => cdp.send(m, p, sessionId);
    cdp.listeners.push((msg) => {
      if (msg.sessionId !== sessionId) return;
      const p = msg.params;
      if (msg.method === "Network.requestWillBeSent") {
        const u = p.request.url;
        if (!u.startsWith(origin) && !u.startsWith("data:") && !u.startsWith("blob:")) fail(`request outside the lab: ${u}`);
      } else if (msg.method === "Runtime.consoleAPICalled" && (p.type === "error" || p.type === "assert")) {
        fail(`console error: ${p.args.map((a) => a.value ?? a.description).join(" ")}`);
      } else if (msg.method === "Runtime.exceptionThrown") {
        fail(`exception: ${p.exceptionDetails.exception?.description ?? p.exceptionDetails.text}`);
      }
    });
    await s("Page.enable");
    await s("Runtime.enable");
    await s("Network.enable");
    await s("Emulation.setDeviceMetricsOverride", { width: 1280, height: 1000, deviceScaleFactor: 1, mobile: false });
    const ev = async (expr) => {
      const { result, exceptionDetails } = await s("Runtime.evaluate", { expression: expr, returnByValue: true, awaitPromise: true });
      if (exceptionDetails) throw new Error(`${expr}: ${exceptionDetails.exception?.description ?? exceptionDetails.text}`);
      return result.value;
    };
    const waitFor = async (expr, what, ms = 60000) => {
      const t0 = Date.now();
      while (Date.now() - t0 < ms) {
        if (await ev(expr)) return true;
        await sleep(50);
      }
      throw new Error(`timeout (${ms} ms) waiting for ${what}`);
    };
    const idle = `(() => { const l = window.__lab; return l && l.run && !l.inFlight && !l.pending; })()`;
    const shot = async (name) => {
      await ev(`window.scrollTo(0, 0)`);
      await sleep(150);
      const img = await s("Page.captureScreenshot", { format: "png" });
      writeFileSync(join(shotDir, `${name}.png`), Buffer.from(img.data, "base64"));
    };
    const click = async (x, y) => {
      for (const type of ["mouseMoved", "mousePressed", "mouseReleased"]) {
        await s("Input.dispatchMouseEvent", { type, x, y, button: "left", clickCount: 1 });
      }
    };
    const rect = (id) => ev(`(() => { const r = document.getElementById(${JSON.stringify(id)}).getBoundingClientRect();
      return { x: r.x, y: r.y, w: r.width, h: r.height }; })()`);

    const waitIdle = (what, ms) => waitFor(idle, what, ms);
    const setField = async (key, v) => {
      await ev(`(() => { const f = document.getElementById("f-${key}"); f.value = ${JSON.stringify(String(v))}; f.dispatchEvent(new Event("change")); })()`);
    };
    const pauseAt = async (t) => {
      await ev(`(() => { __lab.playing = false; document.getElementById("play").textContent = "Play"; __lab.simT = ${t}; })()`);
      await sleep(300);
    };
    const shotOf = async (name, id) => {
      await ev(`document.getElementById(${JSON.stringify(id)}).scrollIntoView({ block: "start" })`);
      await sleep(200);
      const r = await ev(`(() => { const r = document.getElementById(${JSON.stringify(id)}).getBoundingClientRect();
        return { x: r.x + scrollX, y: r.y + scrollY, w: r.width, h: r.height }; })()`);
      const img = await s("Page.captureScreenshot", { format: "png", clip: { x: r.x, y: r.y, width: r.w, height: r.h, scale: 1 } });
      writeFileSync(join(shotDir, `${name}.png`), Buffer.from(img.data, "base64"));
    };
    const section = async (name, fn) => {
      try { await fn(); } catch (e) { fail(`${name}: ${e.message}`); }
    };
    const pixel = (id, x, y) => ev(`Array.from(document.getElementById(${JSON.stringify(id)}).getContext("2d").getImageData(${Math.round(x)}, ${Math.round(y)}, 1, 1).data)`);
    const near = (px, hex, tol) => {
      const c = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
      return c.every((v, i) => Math.abs(v - px[i]) <= tol);
    };

    // 1. URL query parameters preset the sliders
    await section("query", async () => {
      const loaded = cdp.once("Page.loadEventFired", 30000);
      await s("Page.navigate", { url: `${lab.url}?scene=authors&mu=0.55&theta0_rad=0.35` });
      await loaded;
      await waitIdle("the first run");
      const preset = await ev(`[document.getElementById("f-mu").value, document.getElementById("f-theta0_rad").value,
        document.getElementById("f-gamma").value, __lab.run.report.params.mu, __lab.run.report.params.scene]`);
      if (preset[0] === "0.55" && preset[1] === "0.35" && preset[2] === "10" && preset[3] === 0.55 && preset[4] === "authors") {
        okm(`query ?scene=authors&mu=0.55&theta0_rad=0.35 preset the sliders (Gamma ${preset[2]} from the authors' scene)`);
      } else fail(`query parameters not applied: ${JSON.stringify(preset)}`);
    });

    // 2. the default page at 1280 px
    const loaded = cdp.once("Page.loadEventFired", 30000);
    await s("Page.navigate", { url: lab.url });
    await loaded;
    await waitIdle("the first run");
    await waitFor(`!!window.__lab.map`, "the speed map", 120000);
    await sleep(1500);
    await shot("lab-1280-initial");

    // 3. the animation advances
    await section("animation", async () => {
      const a0 = await ev(`[__lab.simT, __lab.frame, document.getElementById("anim").toDataURL()]`);
      await sleep(700);
      const a1 = await ev(`[__lab.simT, __lab.frame, document.getElementById("anim").toDataURL()]`);
      if (a1[0] > a0[0] && a1[1] !== a0[1]) okm(`animation advances (t ${a0[0].toFixed(4)} -> ${a1[0].toFixed(4)} s, frame ${a0[1]} -> ${a1[1]})`);
      else fail(`animation does not advance: ${JSON.stringify([a0.slice(0, 2), a1.slice(0, 2)])}`);
      if (a0[2] === a1[2]) fail("the animation canvas did not change");
    });

    // 4. one palette: the book's mode colours (src/plot PALETTE indexed by the scenes'
    // MODE_COLOUR), read from the source text, on the page and in the drawn timeline
    await section("palette", async () => {
      const plot = readFileSync("src/plot/mod.rs", "utf8");
      const pal = [...plot.slice(plot.indexOf("pub const PALETTE")).matchAll(/RGBColor\((\d+), (\d+), (\d+)\)/g)].slice(0, 8)
        .map((m) => `#${[m[1], m[2], m[3]].map((v) => Number(v).toString(16).padStart(2, "0")).join("")}`);
      const gait = readFileSync("src/scenes/stick/mod.rs", "utf8");
      const idx = /MODE_COLOUR: \[usize; 4\] = \[(\d+), (\d+), (\d+), (\d+)\]/.exec(gait).slice(1).map(Number);
      const want = { F: pal[idx[0]], P: pal[idx[1]], L: pal[idx[2]], R: pal[idx[3]] };
      const got = await ev(`Object.fromEntries(Object.entries(MODES).map(([k, m]) => [k, m.color]))`);
      const same = Object.keys(want).every((k) => want[k] === got[k]);
      if (same) okm(`mode colours are the book's: ${JSON.stringify(got)}`);
      else fail(`mode colours: page ${JSON.stringify(got)}, book ${JSON.stringify(want)}`);
      // the timeline's pixels in the middle of the longest pivot stretch
      const at = await ev(`(() => { const f = shown(__lab.run).frames, cv = document.getElementById("timeline");
        let best = [0, 0], i = 0;
        while (i < f.mode.length) { let k = i; while (k < f.mode.length && f.mode[k] === f.mode[i]) k++;
          if (f.mode[i] === "P" && k - i > best[1] - best[0]) best = [i, k]; i = k; }
        const t = (f.t_s[best[0]] + f.t_s[best[1] - 1]) / 2;
        return [TL.left + (cv.width - TL.left - TL.right) * t / __lab.tlEnd, TL.top + TL.strip / 2]; })()`);
      const px = await pixel("timeline", at[0], at[1]);
      if (near(px, want.P, 2)) okm(`the timeline draws pivot in ${want.P} (pixel ${px.slice(0, 3)})`);
      else fail(`timeline pivot pixel ${px} is not ${want.P}`);
    });

    // 5. a slider moved with the mouse: the displayed mean speed is the CLI's
    await section("slider", async () => {
      await ev(`document.getElementById("s-mu").scrollIntoView({ block: "center" })`);
      const r = await rect("s-mu");
      await click(r.x + r.w * 0.3, r.y + r.h / 2);
      await waitFor(`document.getElementById("f-mu").value !== "0.4"`, "the mu slider to move", 5000);
      await waitFor(`${idle} && String(__lab.run.report.params.mu) === document.getElementById("f-mu").value`, "the run of the new mu");
      const mu = await ev(`document.getElementById("f-mu").value`);
      const shownV = await ev(`[document.getElementById("speed-value").textContent, document.getElementById("speed-value").dataset.mps]`);
      const ref = cli(["--mu", mu]);
      if (ref.code !== 0) fail(`CLI failed for --mu ${mu}: ${ref.stderr}`);
      else {
        const v = ref.json.results.mean_velocity_mps;
        const want = `${fmt(v * 1e3, 4)} mm/s`;
        if (shownV[0] === want && Number(shownV[1]) === v) okm(`slider mu -> ${mu}: page shows ${shownV[0]}, CLI mean_velocity_mps ${v}`);
        else fail(`mean speed: page ${JSON.stringify(shownV)}, CLI ${v} (${want})`);
      }
    });

    // 6. latency: slider input to the first frame drawn with the new run
    await section("latency", async () => {
      const lat = [];
      await ev(`__lab.timings.length = 0`);
      for (const v of ["0.45", "0.5", "0.38", "0.42", "0.47", "0.36", "0.41", "0.44"]) {
        await ev(`__lab.latencies.length = 0`);
        await sleep(100);
        await ev(`(() => { const el = document.getElementById("s-mu"); el.value = "${v}"; el.dispatchEvent(new Event("input")); })()`);
        await waitFor(`__lab.latencies.length > 0 && ${idle}`, "the latency probe");
        lat.push(await ev(`__lab.latencies[0]`));
      }
      lat.sort((x, y) => x - y);
      const med = lat[Math.floor(lat.length / 2)];
      const tm = await ev(`__lab.timings`);
      const median = (xs) => xs.slice().sort((x, y) => x - y)[Math.floor(xs.length / 2)];
      const parts = ["answer", "server", "redraw", "frame"].map((k) => `${k} ${median(tm.map((t) => t[k])).toFixed(1)}`);
      console.log(`latency parts, medians in ms (answer: input to parsed answer, of which server: the run and its stroboscope; redraw: numbers, timeline, map; frame: wait for the animation frame): ${parts.join(", ")}`);
      console.log(`latency slider -> redrawn animation (2 s simulated, ${lat.length} moves): median ${med.toFixed(1)} ms, min ${lat[0].toFixed(1)} ms, max ${lat[lat.length - 1].toFixed(1)} ms`);
      writeFileSync(join(shotDir, "latency.txt"), `${lat.map((x) => x.toFixed(1)).join(" ")}\n`);
    });

    // 7. an out-of-range value shows the CLI's own reason
    await section("invalid", async () => {
      await setField("mu", "5");
      await waitFor(`!document.getElementById("error").hidden && ${idle}`, "the error line", 10000);
      const shownErr = await ev(`document.getElementById("error").textContent`);
      const refErr = cli(["--mu", "5"]);
      if (refErr.code === 2 && shownErr === refErr.stderr) okm(`mu = 5 shows the CLI's line: ${shownErr}`);
      else fail(`error line: page ${JSON.stringify(shownErr)}, CLI (exit ${refErr.code}) ${JSON.stringify(refErr.stderr)}`);
      await shot("lab-1280-invalid");
      await setField("mu", "0.4");
      await waitFor(`document.getElementById("error").hidden && ${idle}`, "the error to clear", 10000);
    });

    // 8. a click on the map sets theta_0 and mu
    await section("map click", async () => {
      const target = [0.6, 0.7];
      await ev(`document.getElementById("map").scrollIntoView({ block: "center" })`);
      const at = await ev(`(() => { const G = mapGeom(), r = document.getElementById("map").getBoundingClientRect(), c = document.getElementById("map");
        return [r.x + G.X(${target[0]}) * r.width / c.width, r.y + G.Y(${target[1]}) * r.height / c.height]; })()`);
      await click(at[0], at[1]);
      await waitFor(`${idle} && __lab.run.report.params.mu !== 0.4`, "the run of the clicked point");
      const got = await ev(`[Number(document.getElementById("f-theta0_rad").value), Number(document.getElementById("f-mu").value),
        __lab.run.report.params.theta0_rad, __lab.run.report.params.mu]`);
      if (Math.abs(got[0] - target[0]) < 0.01 && Math.abs(got[1] - target[1]) < 0.01 && got[2] === got[0] && got[3] === got[1]) {
        okm(`map click at (${target}) set theta0_rad ${got[0]}, mu ${got[1]} and ran them`);
      } else fail(`map click: wanted ${target}, got ${JSON.stringify(got)}`);
      await sleep(800);
      const q = new URLSearchParams(await ev(`location.search`));
      if (Number(q.get("theta0_rad")) === got[0] && Number(q.get("mu")) === got[1]) okm(`the address carries the parameters`);
      else fail(`address bar not updated: ${q}`);
    });

    // 9. logarithmic sliders; values as typed
    await ev(`document.getElementById("preset-jamming").click()`);
    await waitFor(`${idle} && __lab.run.report.params.mu === 0.4`, "the jamming run");
    await section("log slider", async () => {
      await setField("frequency_hz", "30");
      await waitIdle("the run at 30 Hz");
      const r = await ev(`(() => { const s = document.getElementById("s-frequency_hz");
        return [document.getElementById("f-frequency_hz").value, (s.value - s.min) / (s.max - s.min), __lab.run.report.params.frequency_hz]; })()`);
      if (r[0] === "30" && r[1] > 0.45 && r[1] < 0.55 && Math.abs(r[2] - 30) < 1e-9) okm(`f typed as 30 shows "30" and sits at ${(100 * r[1]).toFixed(1)} % of its log slider (1 to 1000 Hz)`);
      else fail(`f = 30: field ${JSON.stringify(r[0])}, slider at ${r[1]}, run ${r[2]}`);
      await ev(`document.getElementById("s-frequency_hz").scrollIntoView({ block: "center" })`);
      const sr = await rect("s-frequency_hz");
      await click(sr.x + sr.w * 0.25, sr.y + sr.h / 2);
      await waitIdle("the run of the moved f slider");
      const t = await ev(`document.getElementById("f-frequency_hz").value`);
      const sig = t.replace(".", "").replace(/^0+/, "").length;
      if (/^\d+(\.\d+)?$/.test(t) && sig <= 3 && Number(t) > 3 && Number(t) < 10) okm(`the f slider at a quarter reads "${t}" Hz (3 significant digits, log scale)`);
      else fail(`f slider at a quarter reads ${JSON.stringify(t)}`);
      const texts = await ev(`PARAMS.map((p) => document.getElementById("f-" + p.key).value)`);
      const noisy = texts.filter((x) => /\d{9,}/.test(x));
      if (noisy.length === 0) okm(`every field shows a short value: ${texts.join(", ")}`);
      else fail(`fields with rounding noise: ${noisy}`);
      await setField("frequency_hz", "30");
      await waitIdle("back to 30 Hz");
    });

    // 10. nice ticks on the timeline
    await section("timeline ticks", async () => {
      const tk = await ev(`__lab.tlTicks`);
      const nice = (labels) => {
        const v = labels.map(Number), d = v[1] - v[0];
        const m = d / Math.pow(10, Math.floor(Math.log10(d)));
        return v.length >= 3 && [1, 2, 5].some((x) => Math.abs(m - x) < 1e-9) &&
          v.every((x, i) => Math.abs(x - v[0] - i * d) < 1e-9 * d) && labels.every((l) => l.length <= 6);
      };
      if (nice(tk.t) && tk.t[0] === "0" && nice(tk.x)) okm(`timeline ticks: t ${tk.t.join(" ")} s, x_C ${tk.x.join(" ")} mm`);
      else fail(`timeline ticks not nice: ${JSON.stringify(tk)}`);
    });

    // 11. the contact force on top of the rod, with the friction cone
    await section("force on top", async () => {
      const f = await ev(`(() => { const f = shown(__lab.run).frames; let n = 0, along = [];
        for (let i = 0; i < f.mode.length; i++) if (f.mode[i] === "P") { n++;
          const d = Math.abs(Math.atan2(f.f_x_n[i], f.f_z_n[i]) - f.theta_rad[i]);
          if (d < 0.1 && Math.hypot(f.f_x_n[i], f.f_z_n[i]) > 0.5 * __lab.run.scene.weight_n) along.push([f.t_s[i], d]); }
        along.sort((a, b) => a[1] - b[1]); return [n, along.length, along.length ? along[0][0] : null]; })()`);
      if (f[2] === null) { fail(`no pivot frame with the force along the rod (of ${f[0]})`); return; }
      await pauseAt(f[2]);
      const a = await ev(`__lab.draw.arrow`);
      const probes = [];
      for (const k of [0.45, 0.6, 0.75]) probes.push(await pixel("anim", a[0] + k * (a[2] - a[0]), a[1] + k * (a[3] - a[1])));
      if (probes.every((px) => near(px, "#b3261e", 30))) okm(`force drawn on top of the rod where they are within 0.1 rad (${f[1]} of ${f[0]} pivot frames); pixels ${probes.map((p) => p.slice(0, 3).join("/")).join(", ")}`);
      else fail(`force arrow hidden along the rod: pixels ${JSON.stringify(probes)}`);
      await shotOf("lab-1280-force-on-top", "anim");
    });

    // 12. the foot close-up: a hop read on the millimetre scale
    await section("foot close-up", async () => {
      await ev(`document.getElementById("preset-authors").click()`);
      await waitFor(`${idle} && __lab.run.report.params.scene === "authors"`, "the authors' run");
      const hop = await ev(`(() => { const f = shown(__lab.run).frames; let best = [0, 0];
        for (let i = 0; i < f.mode.length; i++) if (f.mode[i] === "F" && f.z_c_m[i] - f.plate_z_m[i] > best[1]) best = [f.t_s[i], f.z_c_m[i] - f.plate_z_m[i]];
        return best; })()`);
      await pauseAt(hop[0]);
      const d = await ev(`[__lab.draw.footGapPx, __lab.draw.footPxPerMm, document.getElementById("hop-height").textContent]`);
      const readMm = d[0] / d[1];
      if (Math.abs(readMm - hop[1] * 1e3) < 0.02 * hop[1] * 1e3 + 0.5 / d[1] && d[1] * 0.3 >= 6 && d[2] === `${fmt(hop[1] * 1e3, 3)} mm`) {
        okm(`foot close-up: the highest hop, ${fmt(hop[1] * 1e3, 3)} mm, spans ${d[0].toFixed(1)} px at ${d[1].toFixed(1)} px/mm (0.3 mm = ${(0.3 * d[1]).toFixed(1)} px)`);
      } else fail(`foot close-up: gap ${d[0]} px at ${d[1]} px/mm reads ${readMm} mm, frames ${hop[1] * 1e3} mm, table ${d[2]}`);
      await shotOf("lab-1280-foot", "footbox");
      await shot("lab-1280-authors-flight");
    });

    // 13. take data: trajectory CSV, switches CSV, summary JSON
    await section("downloads", async () => {
      const dl = join(shotDir, "downloads");
      mkdirSync(dl, { recursive: true });
      await cdp.send("Browser.setDownloadBehavior", { behavior: "allow", downloadPath: dl });
      for (const id of ["dl-traj", "dl-csv", "dl-json"]) await ev(`document.getElementById("${id}").click()`);
      const files = ["stick-trajectory.csv", "stick-switches.csv", "stick-run.json"];
      const t0 = Date.now();
      while (!files.every((f) => existsSync(join(dl, f))) && Date.now() - t0 < 10000) await sleep(100);
      const missing = files.filter((f) => !existsSync(join(dl, f)));
      if (missing.length) { fail(`downloads missing: ${missing}`); return; }
      const rows = readFileSync(join(dl, files[0]), "utf8").trim().split("\n");
      const summary = JSON.parse(readFileSync(join(dl, files[2]), "utf8"));
      const ref = cli(["--scene", "authors"]);
      const n = await ev(`shown(__lab.run).frames.t_s.length`);
      const last = rows[rows.length - 1].split(","), first = rows[1].split(",");
      const vCsv = (Number(last[2]) - Number(first[2])) / (Number(last[0]) - Number(first[0]));
      const v = summary.results.mean_velocity_mps;
      const sw = readFileSync(join(dl, files[1]), "utf8");
      if (rows[0] === "t_s,theta_rad,x_c_m,z_c_m,z_s_m,f_x_n,f_z_n,mode" && rows.length === n + 1 && rows.every((r) => r.split(",").length === 8) &&
        Math.abs(vCsv - v) < 2e-3 * Math.abs(v) + 1e-7 && ref.code === 0 && v === ref.json.results.mean_velocity_mps && sw.split("\n").length > 2) {
        okm(`downloads: trajectory CSV (${n} frames, x_C slope ${fmt(vCsv * 1e3, 4)} mm/s), switches CSV (${sw.split("\n").length - 1} lines), summary JSON (the CLI's ${fmt(v * 1e3, 4)} mm/s)`);
      } else fail(`downloads: header ${rows[0]}, ${rows.length} rows for ${n} frames, v ${vCsv} vs ${v} vs CLI ${ref.json && ref.json.results.mean_velocity_mps}`);
    });

    // 14. the stroboscope: the multiplier of the self-locking gait
    await section("stroboscope", async () => {
      await ev(`document.getElementById("preset-jamming").click()`);
      await waitFor(`${idle} && __lab.run.report.params.scene === "jamming" && __lab.run.report.params.gamma === 3`, "the jamming run");
      await setField("duration_s", "4");
      await waitFor(`${idle} && __lab.run.report.params.duration_s === 4`, "the 4 s run");
      const c = await ev(`__lab.run.cycle`);
      const ch6 = readFileSync("chapters/06-stick-state-machine.md", "utf8");
      const row = ch6.split("\n").find((l) => l.startsWith("| self-locking | period-1 |"));
      const published = row ? Number(row.split("|")[8]) : NaN;
      const lead = c.fixed && c.fixed.leading_modulus;
      if (c.fixed && c.fixed.period === 1 && Math.abs(lead - published) < 1e-3 && Math.abs(c.observed_ratio - lead) < 0.05 * lead) {
        okm(`stroboscope: period 1, |lambda| = ${lead} (chapter 6's saltation value ${published}); the samples shrink by ${c.observed_ratio} per cycle`);
      } else fail(`stroboscope: ${JSON.stringify(c.fixed)}, observed ${c.observed_ratio}, chapter 6 ${published}`);
      await shotOf("lab-1280-strobe", "cyclebox");
      await setField("duration_s", "2");
      await waitIdle("back to 2 s");
    });

    // 15. the kept run, standing on its own plate
    await section("kept run", async () => {
      await ev(`document.getElementById("keep").click()`);
      await setField("gamma", "4");
      await waitFor(`${idle} && __lab.runBody.gamma === "4" && !!__lab.cmp`, "the compared run");
      const t = await ev(`(() => { const f = shown(__lab.cmp).frames; const i = f.mode.indexOf("P", f.mode.length >> 1); return f.t_s[i]; })()`);
      await pauseAt(t);
      const k = await ev(`__lab.draw.cmp`);
      if (k && k.mode !== "F" && Math.abs(k.foot[1] - k.plateY) < 1) okm(`kept run in ${k.mode}: its foot at y ${k.foot[1].toFixed(1)} px on its own plate at ${k.plateY.toFixed(1)} px`);
      else fail(`kept run not on its plate: ${JSON.stringify(k)}`);
      await shot("lab-1280-compare");
      await ev(`document.getElementById("clear-compare").click()`);
    });

    // 16. chapter 8: the rod with its mass, the massless ghost beside it
    await section("rod mass", async () => {
      await ev(`document.getElementById("preset-jamming").click()`);
      await waitFor(`${idle} && __lab.run.report.params.gamma === 3`, "the jamming run");
      await setField("rod_mass_kg", "0.5");
      await waitFor(`${idle} && !!__lab.run.rod`, "the rod's run", 120000);
      await ev(`__lab.playing = true`);
      await sleep(600);
      const r = await ev(`[__lab.run.rod.outcome, __lab.run.rod.mean_velocity_mps, __lab.run.rod.ghost.mean_velocity_mps,
        document.getElementById("speed-value").dataset.mps, !!__lab.draw.ghost, document.getElementById("ghost-line").textContent]`);
      const ref = cli8(["--rod-mass-kg", "0.5", "--tip-mass-kg", "1"]);
      const want = ref.json && ref.json.results;
      if (r[0] === "completed" && Number(r[3]) === r[1] && r[4] && want && Math.abs(r[1] - want.mean_velocity_mps) <= 1e-9 + 1e-6 * Math.abs(want.mean_velocity_mps)) {
        okm(`rod of 0.5 kg: ${fmt(r[1] * 1e3, 4)} mm/s (chapter 8's CLI ${fmt(want.mean_velocity_mps * 1e3, 4)} mm/s), ghost ${fmt(r[2] * 1e3, 4)} mm/s drawn`);
      } else fail(`rod: page ${JSON.stringify(r)}, CLI ${JSON.stringify(want && want.mean_velocity_mps)} (${ref.stderr || ""})`);
      await pauseAt(1.0);
      await shot("lab-1280-rod");
      await setField("rod_mass_kg", "0");
      await waitFor(`${idle} && !__lab.run.rod`, "the massless run");
      await ev(`__lab.playing = true`);
    });

    // 17. the guided tasks, each checked by the page
    await section("tasks", async () => {
      // walk backwards: lean the stick the other way
      await setField("theta0_rad", "-0.3");
      await waitFor(`${idle} && !!__lab.tasks.backwards`, "the task 'walk backwards'", 60000).catch(() => {});
      await ev(`document.getElementById("preset-jamming").click()`);
      await waitFor(`${idle} && __lab.run.report.params.gamma === 3 && __lab.run.report.params.mu === 0.4`, "the jamming run");
      for (const g of TASK_ONSET) { await setField("gamma", g); await waitFor(`${idle} && __lab.runBody.gamma === "${g}"`, `Gamma ${g}`); }
      await ev(`document.getElementById("preset-jamming").click()`);
      await waitFor(`${idle} && __lab.run.report.params.gamma === 3 && __lab.run.report.params.mu === 0.4`, "the jamming run");
      for (const [k, v] of TASK_UNSTABLE) { await setField(k, v); await waitIdle(`${k} = ${v}`); }
      await sleep(300);
      const done = await ev(`__lab.tasks`);
      for (const id of ["backwards", "onset", "unstable"]) {
        if (done[id]) okm(`task ${id}: ${done[id]}`);
        else fail(`task ${id} not checked done`);
      }
      await shotOf("lab-1280-tasks", "side");
    });

    // 18. 400 px wide
    await section("400 px", async () => {
      await s("Emulation.setDeviceMetricsOverride", { width: 400, height: 860, deviceScaleFactor: 1, mobile: true });
      const ld = cdp.once("Page.loadEventFired", 30000);
      await s("Page.navigate", { url: lab.url });
      await ld;
      await waitIdle("the first run at 400 px");
      await waitFor(`!!window.__lab.map`, "the speed map", 120000);
      await sleep(1200);
      await shot("lab-400-top");
      const lay = await ev(`(() => { const out = [];
        for (const el of document.querySelectorAll("section, canvas, button, input, select, table")) {
          const r = el.getBoundingClientRect(); if (r.width && (r.left < -0.5 || r.right > 400.5)) out.push((el.id || el.tagName) + " " + r.left.toFixed(0) + ".." + r.right.toFixed(0)); }
        const a = document.getElementById("anim").getBoundingClientRect(), p = document.getElementById("play").getBoundingClientRect();
        return [document.documentElement.scrollWidth, out, a.width, p.bottom]; })()`);
      if (lay[0] <= 400 && lay[1].length === 0 && lay[2] >= 360 && lay[3] < 860) okm(`400 px: no horizontal overflow, animation ${lay[2].toFixed(0)} px wide, Play on the first screen (bottom ${lay[3].toFixed(0)} px)`);
      else fail(`400 px layout: scrollWidth ${lay[0]}, outside: ${lay[1].join("; ")}, animation ${lay[2]}, play at ${lay[3]}`);
      const m = await s("Page.getLayoutMetrics");
      const h = Math.ceil(m.cssContentSize ? m.cssContentSize.height : m.contentSize.height);
      const img = await s("Page.captureScreenshot", { format: "png", captureBeyondViewport: true, clip: { x: 0, y: 0, width: 400, height: h, scale: 1 } });
      writeFileSync(join(shotDir, "lab-400-full.png"), Buffer.from(img.data, "base64"));
    });
  } finally {
    const exited = new Promise((r) => proc.once("exit", r));
    proc.kill();
    lab.proc.kill();
    await Promise.race([exited, sleep(10000)]);
    try { rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 200 }); } catch (e) { /* a leftover profile is no failure */ }
  }
  if (failures.length > 0) {
    console.error(`lab browser test: ${failures.length} failure(s); screenshots in ${shotDir}`);
    process.exit(1);
  }
  console.log(`lab browser test: all checks passed; screenshots in ${shotDir}`);
}

main().catch((e) => {
  console.error(`lab browser test: ${e.stack || e}`);
  process.exit(1);
});
