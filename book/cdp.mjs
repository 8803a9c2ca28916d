// Headless Chromium driven over the DevTools protocol, shared by the book's browser test
// (browser-test.mjs) and the lab's (lab-test.mjs): Node's built-in WebSocket, no npm
// package. `launchChromium` starts a fresh profile and resolves with the browser's
// DevTools address; `Cdp` sends commands and waits for events.
import { spawn } from "node:child_process";
import { mkdtempSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

/// Starts `bin` headless with an empty profile (prefix `prefix` in the temp folder) and
/// a `width,height` window; resolves with `{ proc, profile, browserUrl }`.
export function launchChromium(bin, prefix, windowSize) {
  const profile = mkdtempSync(join(tmpdir(), prefix));
  const args = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-extensions", "--disable-sync", "--no-first-run", "--no-default-browser-check",
    "--hide-scrollbars", "--mute-audio", `--user-data-dir=${profile}`, "--remote-debugging-port=0",
    `--window-size=${windowSize}`, "about:blank"];
  const proc = spawn(bin, args, { stdio: ["ignore", "ignore", "pipe"] });
  return new Promise((ok, fail) => {
    let err = "";
    const timer = setTimeout(() => fail(new Error(`chromium did not start:\n${err}`)), 30000);
    proc.stderr.on("data", (d) => {
      err += d;
      const m = /DevTools listening on (ws:\/\/[^\s]+)/.exec(err);
      if (m) { clearTimeout(timer); ok({ proc, profile, browserUrl: m[1] }); }
    });
    proc.on("exit", (code) => fail(new Error(`chromium exited (${code}):\n${err}`)));
  });
}

/// A DevTools-protocol connection: `send` a command (optionally to a session), `once`
/// waits for an event.
export class Cdp {
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
    return new Promise((ok, fail) => { this.ws.onopen = ok; this.ws.onerror = fail; });
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
