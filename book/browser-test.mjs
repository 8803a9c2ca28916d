// Opens every page of the built book (target/book) in headless Chromium over the DevTools
// protocol and fails on: a broken image, a dead internal link or anchor, a KaTeX error
// element, raw `$` math left in the text, a console error or a failed resource load (a
// KaTeX font, say). Saves a screenshot of the top of every page and a full-page one of
// every chapter under target/book-screenshots/.
//
// Usage: node --experimental-websocket book/browser-test.mjs [chromium binary]
// (Node 20 needs the flag for its built-in WebSocket; Node 22 has it by default.)
import { spawn } from "node:child_process";
import { existsSync, mkdirSync, mkdtempSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const bookDir = resolve("target/book");
const shotDir = resolve("target/book-screenshots");
const chromiumBin = process.argv[2] || "chromium";

function pages() {
  const list = ["index.html", "preface.html", "print.html"];
  for (const f of readdirSync(join(bookDir, "chapters")).sort()) {
    if (f.endsWith(".html")) list.push(`chapters/${f}`);
  }
  return list.filter((p) => existsSync(join(bookDir, p)));
}

function launch() {
  const profile = mkdtempSync(join(tmpdir(), "book-test-"));
  const args = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-extensions",
    "--disable-sync",
    "--no-first-run",
    "--no-default-browser-check",
    "--hide-scrollbars",
    "--mute-audio",
    `--user-data-dir=${profile}`,
    "--remote-debugging-port=0",
    "--window-size=1280,1600",
    "about:blank",
  ];
  const proc = spawn(chromiumBin, args, { stdio: ["ignore", "ignore", "pipe"] });
  return new Promise((ok, fail) => {
    let err = "";
    const timer = setTimeout(() => fail(new Error(`chromium did not start:\n${err}`)), 30000);
    proc.stderr.on("data", (d) => {
      err += d;
      const m = /DevTools listening on (ws:\/\/[^\s]+)/.exec(err);
      if (m) {
        clearTimeout(timer);
        ok({ proc, profile, browserUrl: m[1] });
      }
    });
    proc.on("exit", (code) => fail(new Error(`chromium exited (${code}):\n${err}`)));
  });
}

class Cdp {
  constructor(url) {
    this.ws = new WebSocket(url);
    this.id = 0;
    this.pending = new Map();
    this.listeners = [];
    this.ws.onmessage = (ev) => {
      const msg = JSON.parse(ev.data);
      if (msg.id && this.pending.has(msg.id)) {
        const { ok, fail } = this.pending.get(msg.id);
        this.pending.delete(msg.id);
        if (msg.error) fail(new Error(JSON.stringify(msg.error)));
        else ok(msg.result);
      } else if (msg.method) {
        for (const l of this.listeners) l(msg);
      }
    };
  }
  open() {
    return new Promise((ok, fail) => {
      this.ws.onopen = ok;
      this.ws.onerror = fail;
    });
  }
  send(method, params = {}, sessionId) {
    const id = ++this.id;
    const msg = { id, method, params };
    if (sessionId) msg.sessionId = sessionId;
    this.ws.send(JSON.stringify(msg));
    return new Promise((ok, fail) => this.pending.set(id, { ok, fail }));
  }
  once(method, timeoutMs) {
    return new Promise((ok, fail) => {
      const timer = setTimeout(() => fail(new Error(`timeout waiting for ${method}`)), timeoutMs);
      const l = (msg) => {
        if (msg.method === method) {
          clearTimeout(timer);
          this.listeners = this.listeners.filter((x) => x !== l);
          ok(msg);
        }
      };
      this.listeners.push(l);
    });
  }
}

// Runs in the page: everything the test reads from the rendered DOM.
const inspect = `(() => {
  const main = document.querySelector("main") || document.body;
  const brokenImages = [...document.images]
    .filter((i) => !i.complete || i.naturalWidth === 0)
    .map((i) => i.getAttribute("src"));
  const katexErrors = [...document.querySelectorAll(".katex-error")].map((e) => e.textContent.slice(0, 80));
  const rawMath = [];
  const walker = document.createTreeWalker(main, NodeFilter.SHOW_TEXT);
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (n.parentElement.closest("code, pre, .katex, script, style")) continue;
    if (/\\$/.test(n.textContent)) rawMath.push(n.textContent.trim().slice(0, 80));
  }
  const links = [...document.querySelectorAll("a[href]")].map((a) => a.href);
  const ids = [...document.querySelectorAll("[id]")].map((e) => e.id)
    .concat([...document.querySelectorAll("a[name]")].map((e) => e.name));
  const katexCount = document.querySelectorAll(".katex").length;
  const katexFont = getComputedStyle(document.querySelector(".katex") || document.body).fontFamily;
  return JSON.stringify({ brokenImages, katexErrors, rawMath, links, ids, katexCount, katexFont,
    height: document.documentElement.scrollHeight });
})()`;

async function main() {
  const list = pages();
  if (list.length < 3) throw new Error(`no book in ${bookDir}: run scripts/book-build.sh`);
  rmSync(shotDir, { recursive: true, force: true });
  mkdirSync(shotDir, { recursive: true });
  const { proc, profile, browserUrl } = await launch();
  const failures = [];
  try {
    const cdp = new Cdp(browserUrl);
    await cdp.open();
    const { targetId } = await cdp.send("Target.createTarget", { url: "about:blank" });
    const { sessionId } = await cdp.send("Target.attachToTarget", { targetId, flatten: true });
    const s = (m, p) => cdp.send(m, p, sessionId);
    let current = "";
    const requests = new Map();
    cdp.listeners.push((msg) => {
      if (msg.sessionId !== sessionId) return;
      const p = msg.params;
      if (msg.method === "Network.requestWillBeSent") requests.set(p.requestId, p.request.url);
      if (msg.method === "Runtime.consoleAPICalled" && (p.type === "error" || p.type === "assert")) {
        failures.push(`${current}: console error: ${p.args.map((a) => a.value ?? a.description).join(" ")}`);
      } else if (msg.method === "Runtime.exceptionThrown") {
        failures.push(`${current}: exception: ${p.exceptionDetails.exception?.description ?? p.exceptionDetails.text}`);
      } else if (msg.method === "Log.entryAdded" && p.entry.level === "error") {
        failures.push(`${current}: console error: ${p.entry.text} ${p.entry.url ?? ""}`);
      } else if (msg.method === "Network.loadingFailed" && !p.canceled) {
        failures.push(`${current}: failed load: ${p.errorText} ${requests.get(p.requestId) ?? p.requestId}`);
      }
    });
    await s("Page.enable");
    await s("Runtime.enable");
    await s("Log.enable");
    await s("Network.enable");
    await s("Emulation.setDeviceMetricsOverride", { width: 1280, height: 1600, deviceScaleFactor: 1, mobile: false });
    const seen = new Map();
    const allLinks = [];
    for (const page of list) {
      current = page;
      const url = pathToFileURL(join(bookDir, page)).href;
      const loaded = cdp.once("Page.loadEventFired", 30000);
      await s("Page.navigate", { url });
      await loaded;
      await new Promise((r) => setTimeout(r, 400));
      await s("Runtime.evaluate", { expression: "document.fonts.ready.then(() => 0)", awaitPromise: true });
      const { result } = await s("Runtime.evaluate", { expression: inspect, returnByValue: true });
      const info = JSON.parse(result.value);
      seen.set(url, new Set(info.ids));
      for (const src of info.brokenImages) failures.push(`${page}: broken image ${src}`);
      for (const e of info.katexErrors) failures.push(`${page}: KaTeX error: ${e}`);
      for (const t of info.rawMath) failures.push(`${page}: raw $ in text: ${t}`);
      if (info.katexCount > 0 && !/KaTeX/.test(info.katexFont)) {
        failures.push(`${page}: math not in KaTeX fonts (font-family ${info.katexFont})`);
      }
      for (const href of info.links) allLinks.push({ page, href });
      const name = page.replace(/\//g, "_").replace(/\.html$/, "");
      const top = await s("Page.captureScreenshot", { format: "png" });
      writeFileSync(join(shotDir, `${name}.png`), Buffer.from(top.data, "base64"));
      if (page.startsWith("chapters/")) {
        const height = Math.min(info.height, 16000);
        const full = await s("Page.captureScreenshot", {
          format: "png",
          captureBeyondViewport: true,
          clip: { x: 0, y: 0, width: 1280, height, scale: 0.5 },
        });
        writeFileSync(join(shotDir, `${name}-full.png`), Buffer.from(full.data, "base64"));
        // The exercises with every solution opened, at full scale.
        const { result: top } = await s("Runtime.evaluate", {
          expression: `(() => { document.querySelectorAll("details").forEach((d) => (d.open = true));
            const h = document.getElementById("exercises");
            return h ? h.getBoundingClientRect().top + window.scrollY : -1; })()`,
          returnByValue: true,
        });
        if (top.value >= 0) {
          const ex = await s("Page.captureScreenshot", {
            format: "png",
            captureBeyondViewport: true,
            clip: { x: 300, y: top.value - 20, width: 980, height: 2400, scale: 1 },
          });
          writeFileSync(join(shotDir, `${name}-exercises.png`), Buffer.from(ex.data, "base64"));
        }
        // Sections asked for by name: BOOK_SHOTS="chapters/07-speed-vs-accuracy.html#8-the-stick-by-three-methods,..."
        for (const want of (process.env.BOOK_SHOTS ?? "").split(",").filter((w) => w.startsWith(page + "#"))) {
          const id = want.slice(page.length + 1);
          const { result: at } = await s("Runtime.evaluate", {
            expression: `(() => { const h = document.getElementById(${JSON.stringify(id)});
              return h ? h.getBoundingClientRect().top + window.scrollY : -1; })()`,
            returnByValue: true,
          });
          if (at.value < 0) throw new Error(`BOOK_SHOTS: no #${id} on ${page}`);
          const sec = await s("Page.captureScreenshot", {
            format: "png",
            captureBeyondViewport: true,
            clip: { x: 300, y: at.value - 20, width: 980, height: 2400, scale: 1 },
          });
          writeFileSync(join(shotDir, `${name}-${id}.png`), Buffer.from(sec.data, "base64"));
        }
      }
      console.log(`ok ${page}: ${info.katexCount} formulas, ${info.links.length} links`);
    }
    // Equations need no JavaScript: a chapter loaded with scripts disabled still has its
    // KaTeX elements, laid out in KaTeX's fonts.
    const probe = list.find((p) => p.startsWith("chapters/02-")) ?? list[list.length - 1];
    current = `${probe} (JavaScript disabled)`;
    await s("Emulation.setScriptExecutionDisabled", { value: true });
    const reloaded = cdp.once("Page.loadEventFired", 30000);
    await s("Page.navigate", { url: pathToFileURL(join(bookDir, probe)).href });
    await reloaded;
    await new Promise((r) => setTimeout(r, 400));
    await s("Emulation.setScriptExecutionDisabled", { value: false });
    const { result: nojs } = await s("Runtime.evaluate", { expression: inspect, returnByValue: true });
    const nojsInfo = JSON.parse(nojs.value);
    if (nojsInfo.katexCount === 0 || !/KaTeX/.test(nojsInfo.katexFont)) {
      failures.push(`${current}: no KaTeX math (${nojsInfo.katexCount} elements, font ${nojsInfo.katexFont})`);
    } else {
      console.log(`ok ${current}: ${nojsInfo.katexCount} formulas in KaTeX fonts`);
    }
    // Internal links: the target file exists; an anchor exists on the target page.
    let internal = 0;
    for (const { page, href } of allLinks) {
      if (!href.startsWith("file:")) continue;
      internal += 1;
      const [base, hash] = href.split("#");
      const path = fileURLToPath(base);
      if (!existsSync(path)) {
        failures.push(`${page}: dead link ${href}`);
        continue;
      }
      if (hash && seen.has(base) && !seen.get(base).has(decodeURIComponent(hash))) {
        failures.push(`${page}: dead anchor ${href}`);
      }
    }
    console.log(`${list.length} pages, ${internal} internal links checked; screenshots in ${shotDir}`);
  } finally {
    // Wait for Chromium to exit before removing its profile (it writes there until it
    // is gone); a leftover temporary profile is no test failure.
    const exited = new Promise((r) => proc.once("exit", r));
    proc.kill();
    await Promise.race([exited, new Promise((r) => setTimeout(r, 10000))]);
    try {
      rmSync(profile, { recursive: true, force: true, maxRetries: 5, retryDelay: 200 });
    } catch (e) {
      console.error(`note: could not remove ${profile}: ${e.message}`);
    }
  }
  if (failures.length > 0) {
    for (const f of failures) console.error(`FAIL ${f}`);
    console.error(`book browser test: ${failures.length} failure(s)`);
    process.exit(1);
  }
  console.log("book browser test: all pages passed");
}

main().catch((e) => {
  console.error(`book browser test: ${e.stack || e}`);
  process.exit(1);
});
