// Browser test of `workbook lab` (issue 23), in headless Chromium over the DevTools
// protocol (the approach of book/browser-test.mjs: no npm package needed). Starts the lab
// on a free loopback port, loads the page and checks, failing on any miss:
//   - the page loads nothing from outside the lab (no CDN) and logs no error;
//   - URL query parameters preset the sliders;
//   - a slider moved with the mouse re-runs the simulator, and the displayed mean speed
//     is the CLI's (`workbook stick-state-machine --json` with the same flags);
//   - the animation advances;
//   - an out-of-range value shows the CLI's own one-line reason;
//   - a click on the speed map sets theta_0 and mu and runs them;
//   - a kept run is overlaid for comparison.
// Measures the time from a slider's input event to the first animation frame drawn with
// the new run (reported, not asserted). Screenshots: target/lab-screenshots/*.png.
//
// Usage: node [--experimental-websocket] book/lab-test.mjs <chromium> <workbook binary>
import { spawn, execFileSync } from "node:child_process";
import { mkdirSync, rmSync, writeFileSync } from "node:fs";
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

/// The page's own number format (page.js `fmt`).
const fmt = (x, d) => (x === 0 ? "0" : Number(x.toPrecision(d)).toString());

async function main() {
  rmSync(shotDir, { recursive: true, force: true });
  mkdirSync(shotDir, { recursive: true });
  const lab = await startLab();
  const origin = lab.url.replace(/\/$/, "");
  const { proc, profile, browserUrl } = await launchChromium(chromiumBin, "lab-test-", "1320,1000");
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
    await s("Emulation.setDeviceMetricsOverride", { width: 1320, height: 1000, deviceScaleFactor: 1, mobile: false });
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

    // 1. URL query parameters preset the sliders
    let loaded = cdp.once("Page.loadEventFired", 30000);
    await s("Page.navigate", { url: `${lab.url}?scene=authors&mu=0.55&theta0_rad=0.35` });
    await loaded;
    await waitFor(idle, "the first run");
    const preset = await ev(`[document.getElementById("f-mu").value, document.getElementById("f-theta0_rad").value,
      document.getElementById("f-gamma").value, __lab.run.report.params.mu, __lab.run.report.params.scene]`);
    if (preset[0] === "0.55" && preset[1] === "0.35" && preset[2] === "10" && preset[3] === 0.55 && preset[4] === "authors") {
      okm(`query ?scene=authors&mu=0.55&theta0_rad=0.35 preset the sliders (Gamma ${preset[2]} from the authors' scene)`);
    } else fail(`query parameters not applied: ${JSON.stringify(preset)}`);

    // 2. the default page
    loaded = cdp.once("Page.loadEventFired", 30000);
    await s("Page.navigate", { url: lab.url });
    await loaded;
    await waitFor(idle, "the first run");
    await waitFor(`!!window.__lab.map`, "the speed map", 120000);
    await sleep(1500);
    await shot("lab-initial");

    // 3. the animation advances
    const a0 = await ev(`[__lab.simT, __lab.frame, document.getElementById("anim").toDataURL()]`);
    await sleep(700);
    const a1 = await ev(`[__lab.simT, __lab.frame, document.getElementById("anim").toDataURL()]`);
    if (a1[0] > a0[0] && a1[1] !== a0[1]) okm(`animation advances (t ${a0[0].toFixed(4)} -> ${a1[0].toFixed(4)} s, frame ${a0[1]} -> ${a1[1]})`);
    else fail(`animation does not advance: ${JSON.stringify([a0.slice(0, 2), a1.slice(0, 2)])}`);
    if (a0[2] === a1[2]) fail("the animation canvas did not change");

    // 4. a slider moved with the mouse: the displayed mean speed is the CLI's
    await ev(`document.getElementById("s-mu").scrollIntoView({ block: "center" })`);
    const r = await rect("s-mu");
    await click(r.x + r.w * 0.3, r.y + r.h / 2);
    await waitFor(`document.getElementById("f-mu").value !== "0.4"`, "the mu slider to move", 5000);
    await waitFor(`${idle} && String(__lab.run.report.params.mu) === document.getElementById("f-mu").value`, "the run of the new mu");
    const mu = await ev(`document.getElementById("f-mu").value`);
    const shown = await ev(`[document.getElementById("speed-value").textContent, document.getElementById("speed-value").dataset.mps]`);
    const ref = cli(["--mu", mu]);
    if (ref.code !== 0) fail(`CLI failed for --mu ${mu}: ${ref.stderr}`);
    else {
      const v = ref.json.results.mean_velocity_mps;
      const want = `${fmt(v * 1e3, 4)} mm/s`;
      if (shown[0] === want && Number(shown[1]) === v) okm(`slider mu -> ${mu}: page shows ${shown[0]}, CLI mean_velocity_mps ${v}`);
      else fail(`mean speed: page ${JSON.stringify(shown)}, CLI ${v} (${want})`);
    }
    await shot("lab-slider");

    // 5. latency: slider input to the first frame drawn with the new run
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
    console.log(`latency parts, medians in ms (answer: input to parsed answer, of which server: the run; redraw: numbers, timeline, map; frame: wait for the animation frame): ${parts.join(", ")}`);
    console.log(`latency slider -> redrawn animation (2 s simulated, ${lat.length} moves): median ${med.toFixed(1)} ms, min ${lat[0].toFixed(1)} ms, max ${lat[lat.length - 1].toFixed(1)} ms`);
    writeFileSync(join(shotDir, "latency.txt"), `${lat.map((x) => x.toFixed(1)).join(" ")}\n`);

    // 6. an out-of-range value shows the CLI's own reason
    await ev(`(() => { const f = document.getElementById("f-mu"); f.value = "5"; f.dispatchEvent(new Event("change")); })()`);
    await waitFor(`!document.getElementById("error").hidden && ${idle}`, "the error line", 10000);
    const shownErr = await ev(`document.getElementById("error").textContent`);
    const refErr = cli(["--mu", "5"]);
    if (refErr.code === 2 && shownErr === refErr.stderr) okm(`mu = 5 shows the CLI's line: ${shownErr}`);
    else fail(`error line: page ${JSON.stringify(shownErr)}, CLI (exit ${refErr.code}) ${JSON.stringify(refErr.stderr)}`);
    await shot("lab-invalid");
    await ev(`(() => { const f = document.getElementById("f-mu"); f.value = "0.4"; f.dispatchEvent(new Event("change")); })()`);
    await waitFor(`document.getElementById("error").hidden && ${idle}`, "the error to clear", 10000);

    // 7. a click on the map sets theta_0 and mu
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
    const search = await ev(`location.search`);
    const q = new URLSearchParams(search);
    if (Number(q.get("theta0_rad")) === got[0] && Number(q.get("mu")) === got[1]) okm(`the address carries the parameters: ${search.slice(0, 60)}...`);
    else fail(`address bar not updated: ${search}`);
    await shot("lab-map-click");

    // 8. comparison overlay: keep this run, change gamma
    await ev(`document.getElementById("keep").click()`);
    await ev(`(() => { const el = document.getElementById("s-gamma"); el.value = "4"; el.dispatchEvent(new Event("input")); })()`);
    await waitFor(`${idle} && __lab.run.report.params.gamma === 4 && !!__lab.cmp`, "the compared run");
    await sleep(1200);
    await shot("lab-compare");
    okm("comparison: kept run overlaid (see lab-compare.png)");

    // 9. the authors' scene, paused at a hop, full page
    await ev(`document.getElementById("preset-authors").click()`);
    await waitFor(`${idle} && __lab.run.report.params.scene === "authors"`, "the authors' run");
    await ev(`(() => { const l = __lab, f = l.run.frames, i = f.mode.indexOf("F");
      l.playing = false; l.simT = i >= 0 ? f.t_s[i + 2] ?? f.t_s[i] : 0; })()`);
    await sleep(1500);
    await shot("lab-authors-flight");
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
