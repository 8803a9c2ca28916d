// The stick lab's drawing: the animation, the foot close-up, the mode timeline and
// x_C(t), the stroboscope, the energy budget and the speed map (with its click). Shares
// the globals of page.js.

// ---------- canvas sizes ----------
// The animation, timeline and stroboscope are drawn at the width they are shown (at
// most their desktop size), so that their text keeps its size on a phone.
function fitCanvases() {
  const fit = (id, maxW, height) => {
    const cv = $(id), w = Math.round(Math.min(maxW, cv.parentElement.clientWidth - 20));
    const h = height(w);
    if (w > 0 && (cv.width !== w || cv.height !== h)) { cv.width = w; cv.height = h; return true; }
    return false;
  };
  const a = fit("anim", 640, (w) => Math.max(260, Math.round((w * 360) / 640)));
  const t = fit("timeline", 640, () => 160);
  const s = fit("strobe", 620, (w) => (w >= 500 ? 220 : 440));
  if ((a || t || s) && lab.run) { drawTimeline(); drawStrobe(); }
}

// ---------- animation ----------
function tick(now) {
  const run = lab.run;
  const f = run && shown(run).frames;
  if (f && f.t_s.length > 0) {
    const tEnd = f.t_s[f.t_s.length - 1];
    if (lab.playing && lab.lastWall !== null) {
      lab.simT += ((now - lab.lastWall) / 1000) * Number($("speed").value);
      if (lab.simT > tEnd) lab.simT = 0;
    }
    lab.frame = frameAt(f, lab.simT);
    drawAnim();
    drawFoot();
    drawCursor();
  }
  lab.lastWall = now;
  requestAnimationFrame(tick);
}

function state(f, i) {
  return {
    t: f.t_s[i], mode: f.mode[i], th: f.theta_rad[i], x: f.x_c_m[i], z: f.z_c_m[i],
    zp: f.plate_z_m[i], fx: f.f_x_n[i], fz: f.f_z_n[i],
  };
}

// The scale of the animation: px per metre, the vertical magnification E (at most 20,
// and to at most 40 px of plate travel) and the height of the plate's mean level.
function animScale(run, H) {
  const sc = run.scene;
  const s = Math.min(190, 0.53 * H) / sc.length_m;
  const ampPx = sc.plate_amplitude_m * s;
  const E = $("magnify").checked ? Math.max(1, Math.min(20, Math.floor(40 / Math.max(ampPx, 1e-9)))) : 1;
  return { s, E, y0: H - 34 - E * ampPx };
}

function drawAnim() {
  const cv = $("anim"), g = cv.getContext("2d");
  const W = cv.width, H = cv.height;
  const run = lab.run, sc = run.scene, f = shown(run).frames;
  const { s, E, y0 } = animScale(run, H);
  const cur = state(f, lab.frame);
  const camX = cur.x;
  const X = (x) => W * 0.42 + (x - camX) * s;
  const Y = (z) => y0 - z * s * E;
  const dr = { E, s }; // this frame's geometry, read by the browser test
  g.clearRect(0, 0, W, H);
  drawPlate(g, W, H, X, Y(cur.zp), camX, s);
  if (lab.cmp) dr.cmp = drawKept(g, X, Y, cur.t, s, E);
  if (run.rod) dr.ghost = drawGhost(g, run, X, Y, cur.t, s);
  drawTrail(g, f, X, Y, sc.period_s);
  const cx = X(cur.x), cy = Y(cur.z);
  const mode = MODES[cur.mode] || MODES.F;
  if (cur.mode !== "F") drawCone(g, cx, cy, sc.mu, 130 * Math.min(1, H / 360));
  const rodLook = run.rod ? rodStyle(run.rod) : { width: 4, tip: 9 };
  const u = Math.min(1, H / 360); // lengths in px scale with a smaller canvas
  drawRod(g, cx, cy, cur.th, s * sc.length_m, mode.color, rodLook);
  const weight = run.rod ? run.rod.total_kg * run.report.params.g_mps2 : sc.weight_n; // M g or m g (N)
  if (cur.mode !== "F") dr.arrow = drawForce(g, cx, cy, cur, weight, u);
  dr.foot = [cx, cy];
  dr.rodEnd = [cx + s * sc.length_m * Math.sin(cur.th), cy - s * sc.length_m * Math.cos(cur.th)];
  g.fillStyle = "#222";
  g.beginPath(); g.arc(cx, cy, 3.5, 0, 2 * Math.PI); g.fill();
  g.font = "12px system-ui, sans-serif";
  g.fillText("C", cx - 14, cy + 4);
  g.fillText("P", dr.rodEnd[0] + 12, dr.rodEnd[1] - 8);
  animLabels(g, W, cur, mode, E);
  lab.draw = dr;
  $("magnify-label").textContent = `vertical motion x${E > 1 ? E : 20}`;
  $("clock").textContent = `t = ${cur.t.toFixed(3)} s  (frame ${lab.frame + 1}/${lab.frameCount})`;
}

function drawPlate(g, W, H, X, yp, camX, s) {
  g.fillStyle = "#dfe4ea";
  g.fillRect(0, yp, W, H - yp);
  g.strokeStyle = "#718096";
  g.lineWidth = 1.5;
  g.beginPath(); g.moveTo(0, yp); g.lineTo(W, yp); g.stroke();
  const step = niceStep(W / s / 12);
  g.fillStyle = "#4a5568";
  g.lineWidth = 1;
  g.font = "11px system-ui, sans-serif";
  for (let k = Math.floor((camX - W / s) / step); k <= Math.ceil((camX + W / s) / step); k++) {
    const px = X(k * step);
    if (px < -2 || px > W + 2) continue;
    g.beginPath(); g.moveTo(px, yp); g.lineTo(px, yp + (k % 5 === 0 ? 12 : 6)); g.stroke();
  }
  g.fillText(`plate ticks every ${fmtLen(step)}; the camera follows C`, 8, H - 8);
}

// The kept run at the same time, grey, standing on its own plate (a dashed line at its
// plate's height): its foot is drawn at its own height above its own plate.
function drawKept(g, X, Y, t, s, E) {
  const cf = shown(lab.cmp).frames;
  const j = frameAt(cf, t);
  if (j < 0) return null;
  const c = state(cf, j);
  const yp = Y(c.zp), fx = X(c.x);
  const footY = yp - (c.z - c.zp) * s * E; // formula: its plate + its own gap, magnified alike
  g.strokeStyle = "rgba(80,80,80,0.75)"; g.lineWidth = 1.5; g.setLineDash([6, 4]);
  g.beginPath(); g.moveTo(fx - 70, yp); g.lineTo(fx + 70, yp); g.stroke();
  g.setLineDash([]);
  g.fillStyle = "rgba(80,80,80,0.9)"; g.font = "11px system-ui, sans-serif";
  g.fillText("kept run, on its plate", fx - 130, yp - 5);
  const len = s * lab.cmp.scene.length_m;
  drawRod(g, fx, footY, c.th, len, "rgba(120,120,120,0.5)", { width: 4, tip: 7 });
  return { foot: [fx, footY], plateY: yp, mode: c.mode };
}

// Chapter 8's ghost: the massless model (all the mass at P), dashed and faded.
function drawGhost(g, run, X, Y, t, s) {
  const gf = run.rod.ghost.frames;
  const k = frameAt(gf, t);
  if (k < 0) return null;
  const c = state(gf, k);
  const len = s * run.scene.length_m;
  const fx = X(c.x), fy = Y(c.z);
  drawRod(g, fx, fy, c.th, len, "rgba(40,40,40,0.35)", { width: 3, tip: 9, dashed: true });
  const px = fx + len * Math.sin(c.th), py = fy - len * Math.cos(c.th);
  g.fillStyle = "rgba(40,40,40,0.75)"; g.font = "11px system-ui, sans-serif";
  g.fillText("ghost: massless model", px + 12, py + 4);
  return { foot: [fx, fy] };
}

function drawTrail(g, f, X, Y, period) {
  const back = Math.max(1, Math.round((3 * period) / f.dt_s));
  g.strokeStyle = "rgba(0,114,178,0.5)";
  g.lineWidth = 1.5;
  g.beginPath();
  const i0 = Math.max(0, lab.frame - back);
  for (let i = i0; i <= lab.frame; i++) {
    const px = X(f.x_c_m[i]), py = Y(f.z_c_m[i]);
    if (i === i0) g.moveTo(px, py); else g.lineTo(px, py);
  }
  g.stroke();
}

// The friction cone at C, as in the book's model figure: a light green sector with
// dashed edges at atan(mu) from the normal.
function drawCone(g, cx, cy, mu, r) {
  const a = Math.atan(mu); // r: as long as the longest force arrow
  const ex = r * Math.sin(a), ey = r * Math.cos(a);
  g.fillStyle = "rgba(46,125,50,0.10)";
  g.beginPath(); g.moveTo(cx, cy); g.lineTo(cx - ex, cy - ey); g.lineTo(cx + ex, cy - ey); g.closePath(); g.fill();
  g.strokeStyle = CONE; g.lineWidth = 1.2; g.setLineDash([5, 4]);
  g.beginPath(); g.moveTo(cx - ex, cy - ey); g.lineTo(cx, cy); g.lineTo(cx + ex, cy - ey); g.stroke();
  g.setLineDash([]);
}

// The contact force on C, drawn last (on top of the rod) with a white halo so that it
// stays visible where it lies along the rod: 150 px per weight, at most the cone's 130
// (times `u`, the canvas's scale).
function drawForce(g, cx, cy, cur, weight, u) {
  const f = Math.hypot(cur.fx, cur.fz) / weight;
  const len = Math.min(130 * u, 150 * u * f);
  if (!(len > 1)) return null;
  const x1 = cx + (len * cur.fx) / (f * weight), y1 = cy - (len * cur.fz) / (f * weight);
  arrow(g, cx, cy, x1, y1, "#fff", 7);
  arrow(g, cx, cy, x1, y1, FORCE, 3);
  g.font = "bold 13px system-ui, sans-serif"; g.fillStyle = FORCE;
  g.fillText("F", x1 + (x1 >= cx ? 6 : -16), y1 - 4);
  return [cx, cy, x1, y1];
}

// The rod's look: its width grows with its share of the mass, the tip's disc with m.
function rodStyle(rod) {
  const share = rod.rod_mass_kg / rod.total_kg;
  return { width: 3 + 9 * share, tip: Math.max(3, 9 * Math.cbrt(rod.tip_mass_kg)), g: rod.l_g_m };
}

function drawRod(g, cx, cy, th, len, color, look) {
  const px = cx + len * Math.sin(th), py = cy - len * Math.cos(th);
  g.strokeStyle = color; g.lineWidth = look.width; g.lineCap = "round";
  if (look.dashed) g.setLineDash([7, 5]);
  g.beginPath(); g.moveTo(cx, cy); g.lineTo(px, py); g.stroke();
  g.setLineDash([]);
  g.fillStyle = color;
  g.beginPath(); g.arc(px, py, look.tip, 0, 2 * Math.PI);
  if (look.dashed) { g.lineWidth = 1.5; g.stroke(); } else g.fill();
  if (look.g !== undefined) {
    // the centre of mass G, l_G from C
    const k = (look.g / lab.run.scene.length_m) * len;
    const gx = cx + k * Math.sin(th), gy = cy - k * Math.cos(th);
    g.fillStyle = "#fff"; g.strokeStyle = "#222"; g.lineWidth = 1.5;
    g.beginPath(); g.arc(gx, gy, 5, 0, 2 * Math.PI); g.fill(); g.stroke();
    g.beginPath(); g.moveTo(gx - 5, gy); g.lineTo(gx + 5, gy); g.moveTo(gx, gy - 5); g.lineTo(gx, gy + 5); g.stroke();
    g.fillStyle = "#222"; g.font = "11px system-ui, sans-serif"; g.fillText("G", gx + 8, gy + 4);
  }
}

function animLabels(g, W, cur, mode, E) {
  g.font = "bold 15px system-ui, sans-serif";
  g.fillStyle = mode.color;
  g.fillText(mode.name, 10, 22);
  g.font = "12px system-ui, sans-serif";
  g.fillStyle = "#444";
  g.fillText(`θ = ${cur.th.toFixed(3)} rad   x_C = ${(cur.x * 1e3).toFixed(2)} mm`, 10, 40);
  if (cur.mode !== "F") {
    g.fillStyle = FORCE;
    g.fillText(`F on C: ${fmt(cur.fx, 3)} N across, ${fmt(cur.fz, 3)} N up (cone: |F_x| ≤ μ F_z)`, 10, 56);
  }
  if (E > 1) { g.fillStyle = "#888"; g.textAlign = "right"; g.fillText(`vertical motion drawn ${E} x larger`, W - 10, 22); g.textAlign = "left"; }
}

function arrow(g, x0, y0, x1, y1, color, w) {
  const a = Math.atan2(y1 - y0, x1 - x0), h = 7 + 2 * w;
  g.strokeStyle = color; g.fillStyle = color; g.lineWidth = w; g.lineCap = "round";
  g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1 - 0.6 * h * Math.cos(a), y1 - 0.6 * h * Math.sin(a)); g.stroke();
  g.beginPath(); g.moveTo(x1, y1);
  g.lineTo(x1 - h * Math.cos(a - 0.4), y1 - h * Math.sin(a - 0.4));
  g.lineTo(x1 - h * Math.cos(a + 0.4), y1 - h * Math.sin(a + 0.4));
  g.closePath(); g.fill();
}

// The smallest of 1, 2, 5 x 10^k at least x.
function niceStep(x) {
  const e = Math.pow(10, Math.floor(Math.log10(x)));
  for (const m of [1, 2, 5, 10]) if (m * e >= x * (1 - 1e-9)) return m * e;
  return 10 * e;
}
// About `n` ticks over [lo, hi] at a nice step, as [values, step].
function niceTicks(lo, hi, n) {
  const step = niceStep((hi - lo) / n);
  const out = [];
  for (let k = Math.ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k++) out.push(k * step);
  return [out, step];
}
// A tick's label: the step's decimals, no rounding noise.
function tickText(v, step) {
  const dec = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  return String(Number((Math.abs(v) < step * 1e-6 ? 0 : v).toFixed(dec)));
}
const fmtLen = (m) => (m >= 0.01 ? `${fmt(m * 100, 3)} cm` : `${fmt(m * 1000, 3)} mm`);

// ---------- foot close-up: true scale, millimetres, in the plate's frame ----------
// The plate's surface stays put at the ruler's 0, so the ruler reads the height of C
// above the plate (a hop) directly; the scale fits the run's highest hop.
function drawFoot() {
  const cv = $("foot"), g = cv.getContext("2d");
  const W = cv.width, H = cv.height;
  const run = lab.run, sc = run.scene, f = shown(run).frames;
  const cur = state(f, lab.frame);
  const hop = lab.hopMm || 0; // mm
  const k = Math.max(4, Math.min(120, (H - 72) / (hop + 0.3))); // px per mm, both directions
  const L = 44; // the ruler's column
  const base = H - 26; // the plate's surface
  const X = (xmm) => L + (W - L) / 2 + (xmm - cur.x * 1e3) * k;
  const Y = (hmm) => base - hmm * k; // height above the plate (mm)
  g.clearRect(0, 0, W, H);
  g.fillStyle = "#dfe4ea"; g.fillRect(L, base, W - L, H - base);
  g.strokeStyle = "#718096"; g.lineWidth = 1.5;
  g.beginPath(); g.moveTo(L, base); g.lineTo(W, base); g.stroke();
  // C's track over the last drive cycle, relative to the plate
  const back = Math.max(1, Math.round(sc.period_s / f.dt_s));
  const i0 = Math.max(0, lab.frame - back);
  g.strokeStyle = "rgba(0,114,178,0.6)"; g.lineWidth = 1.5;
  g.beginPath();
  for (let i = i0; i <= lab.frame; i++) {
    const p = [X(f.x_c_m[i] * 1e3), Y((f.z_c_m[i] - f.plate_z_m[i]) * 1e3)];
    if (i === i0) g.moveTo(...p); else g.lineTo(...p);
  }
  g.stroke();
  const gap = Math.max(0, (cur.z - cur.zp) * 1e3);
  const cx = X(cur.x * 1e3), cy = Y(gap);
  const mode = MODES[cur.mode] || MODES.F;
  g.strokeStyle = mode.color; g.lineWidth = 5; g.lineCap = "round";
  g.beginPath(); g.moveTo(cx, cy); g.lineTo(cx + 400 * Math.sin(cur.th), cy - 400 * Math.cos(cur.th)); g.stroke();
  g.fillStyle = "#222"; g.beginPath(); g.arc(cx, cy, 3.5, 0, 2 * Math.PI); g.fill();
  if (cur.mode === "F" && gap > 0) {
    g.strokeStyle = "#222"; g.lineWidth = 1;
    g.beginPath(); g.moveTo(cx - 10, cy); g.lineTo(cx - 10, base); g.moveTo(cx - 14, cy); g.lineTo(cx - 6, cy); g.moveTo(cx - 14, base); g.lineTo(cx - 6, base); g.stroke();
  }
  footRuler(g, L, H, Y, k, base);
  g.fillStyle = "rgba(251,251,253,0.85)"; g.fillRect(L + 2, 2, W - L - 4, 31);
  g.fillStyle = "#222"; g.font = "12px system-ui, sans-serif";
  g.fillText(cur.mode === "F" ? `C is ${fmt(gap, 3)} mm above the plate` : `C on the plate (${mode.name})`, L + 6, 14);
  g.fillStyle = "#666"; g.font = "11px system-ui, sans-serif";
  g.fillText(hop > 0 ? `highest hop this run: ${fmt(hop, 3)} mm` : "no flight in this run", L + 6, 28);
  g.fillText("plate", W - 34, base + 14);
  lab.draw.footPxPerMm = k;
  lab.draw.footGapPx = cur.mode === "F" ? base - cy : 0;
}

// A vertical ruler in millimetres from the plate's surface: labels every 0.1 to 1 mm
// as the scale allows, minor ticks at a fifth of that.
function footRuler(g, L, H, Y, k, base) {
  const top = base / k;
  const major = niceStep(26 / k), minor = major / 5;
  g.fillStyle = "#fff"; g.fillRect(0, 0, L, H);
  g.strokeStyle = "#444"; g.fillStyle = "#333"; g.lineWidth = 1; g.font = "10px system-ui, sans-serif";
  g.beginPath(); g.moveTo(L - 1, 0); g.lineTo(L - 1, base); g.stroke();
  for (let i = 0; i * minor <= top; i++) {
    const h = i * minor, y = Y(h), big = i % 5 === 0;
    g.beginPath(); g.moveTo(L - 1, y); g.lineTo(L - (big ? 9 : 5), y); g.stroke();
    if (big && y > 8) g.fillText(tickText(h, major), 4, y + 3);
  }
  g.fillText("mm", 4, H - 8);
}

// ---------- timeline: mode strip and x_C(t), nice ticks ----------
const TL = { left: 56, right: 12, top: 6, strip: 16, bottom: 34 };
function drawTimeline() {
  const cv = $("timeline"), g = cv.getContext("2d");
  const W = cv.width, H = cv.height;
  g.clearRect(0, 0, W, H);
  const run = lab.run;
  if (!run) return;
  const f = shown(run).frames, n = f.t_s.length;
  if (n === 0) return;
  const cmpF = lab.cmp ? shown(lab.cmp).frames : null;
  const tEnd = Math.max(f.t_s[n - 1], cmpF ? cmpF.t_s[cmpF.t_s.length - 1] : 0) || 1;
  const X = (t) => TL.left + ((W - TL.left - TL.right) * t) / tEnd;
  for (let i = 0; i < n;) {
    let k = i + 1; // one rectangle per stretch of one mode
    while (k < n && f.mode[k] === f.mode[i]) k++;
    g.fillStyle = (MODES[f.mode[i]] || MODES.F).color;
    const x0 = X(f.t_s[i]), x1 = k < n ? X(f.t_s[k]) : X(f.t_s[n - 1]) + 1;
    g.fillRect(x0, TL.top, Math.max(1, x1 - x0 + 0.5), TL.strip);
    i = k;
  }
  g.fillStyle = "#444"; g.font = "11px system-ui, sans-serif";
  g.fillText("mode", 6, TL.top + 12);
  const sets = [f, cmpF].filter(Boolean);
  let lo = Infinity, hi = -Infinity;
  for (const s of sets) for (const x of s.x_c_m) { lo = Math.min(lo, x); hi = Math.max(hi, x); }
  if (hi - lo < 1e-6) { hi += 5e-4; lo -= 5e-4; }
  const y0 = TL.top + TL.strip + 8, y1 = H - TL.bottom;
  const Y = (x) => y1 - ((y1 - y0) * (x - lo)) / (hi - lo);
  // grid and ticks: x_C in mm, t in s
  const [xt, xs] = niceTicks(lo * 1e3, hi * 1e3, 4);
  const [tt, ts] = niceTicks(0, tEnd, 8);
  g.strokeStyle = "#e6e6e6"; g.lineWidth = 1;
  for (const v of xt) { g.beginPath(); g.moveTo(TL.left, Y(v / 1e3)); g.lineTo(W - TL.right, Y(v / 1e3)); g.stroke(); }
  for (const t of tt) { g.beginPath(); g.moveTo(X(t), y0); g.lineTo(X(t), y1); g.stroke(); }
  g.strokeStyle = "#999"; g.strokeRect(TL.left, y0, W - TL.left - TL.right, y1 - y0);
  g.fillStyle = "#444"; g.textAlign = "right";
  for (const v of xt) g.fillText(tickText(v, xs), TL.left - 4, Y(v / 1e3) + 4);
  g.textAlign = "center";
  for (const t of tt) g.fillText(tickText(t, ts), X(t), y1 + 13);
  g.textAlign = "left";
  sets.forEach((s, k) => {
    g.strokeStyle = k === 0 ? "#2d3748" : "rgba(120,120,120,0.8)";
    g.lineWidth = 1.6;
    g.setLineDash(k === 0 ? [] : [5, 3]);
    g.beginPath();
    s.t_s.forEach((t, i) => { const p = [X(t), Y(s.x_c_m[i])]; if (i) g.lineTo(...p); else g.moveTo(...p); });
    g.stroke();
  });
  g.setLineDash([]);
  g.save(); g.translate(12, (y0 + y1) / 2 + 24); g.rotate(-Math.PI / 2); g.fillText("x_C (mm)", 0, 0); g.restore();
  g.fillText(lab.cmp ? "time t (s)   solid: this run, dashed: kept run; click to jump" : "time t (s)   click to jump", TL.left, H - 4);
  lab.tlImage = g.getImageData(0, 0, W, H);
  lab.tlEnd = tEnd;
  lab.tlTicks = { t: tt.map((t) => tickText(t, ts)), x: xt.map((v) => tickText(v, xs)) };
}

function drawCursor() {
  if (!lab.tlImage) return;
  const cv = $("timeline"), g = cv.getContext("2d");
  g.putImageData(lab.tlImage, 0, 0);
  const x = TL.left + ((cv.width - TL.left - TL.right) * lab.simT) / (lab.tlEnd || 1);
  g.strokeStyle = "#e53e3e"; g.lineWidth = 1.5;
  g.beginPath(); g.moveTo(x, TL.top); g.lineTo(x, cv.height - TL.bottom); g.stroke();
}

// ---------- stroboscope ----------
function drawStrobe() {
  const cv = $("strobe"), g = cv.getContext("2d");
  const W = cv.width, H = cv.height;
  g.clearRect(0, 0, W, H);
  const c = lab.run && lab.run.cycle;
  if (!c) return;
  const fx = c.fixed;
  const lead = fx ? fx.leading_modulus : null;
  const st = $("cycle-status");
  if (fx) {
    const kind = fx.stable ? "stable: the gait returns to itself" : "unstable: the gait drifts away";
    st.textContent = `period ${fx.period}, leading multiplier |λ| = ${fmt(lead, 3)} (${kind})` +
      (c.observed_ratio ? `; the samples shrink by ${fmt(c.observed_ratio, 3)} per cycle` : "") +
      (lab.run.rod ? "; for chapter 6's massless stick with the tip mass m alone (the rod's own map is not computed)" : "");
  } else st.textContent = c.ended ? `(the run ${c.ended} before a gait formed)` : "(no fixed point of period 1 or 2 near the last sample)";
  // side by side, or stacked on a narrow canvas
  const wide = W >= 500;
  strobeDecay(g, c, lead, wide ? { l: 46, r: W / 2 - 10, t: 10, b: H - 30 } : { l: 46, r: W - 10, t: 10, b: H / 2 - 34 });
  strobePhase(g, c, wide ? { l: W / 2 + 52, r: W - 10, t: 10, b: H - 30 } : { l: 52, r: W - 10, t: H / 2 + 6, b: H - 30 });
}

// Left: log10 of each sample's distance to the fixed point against the cycle k, and
// the line |lambda|^k through the first sample inside 1e-2.
function strobeDecay(g, c, lead, P) {
  const d = c.distance.map((v, k) => [k, v]).filter(([, v]) => v !== null && v > 0);
  axesBox(g, P, "drive cycle k", "distance to fixed point");
  if (d.length === 0) return;
  const n = Math.max(1, c.distance.length - 1);
  const lo = Math.max(-12, Math.floor(Math.min(...d.map(([, v]) => Math.log10(v))))), hi = Math.max(lo + 1, Math.ceil(Math.max(...d.map(([, v]) => Math.log10(v)))));
  const X = (k) => P.l + ((P.r - P.l) * k) / n, Y = (e) => P.b - ((P.b - P.t) * (e - lo)) / (hi - lo);
  g.fillStyle = "#444"; g.font = "10px system-ui, sans-serif"; g.textAlign = "right";
  for (let e = lo; e <= hi; e += Math.max(1, Math.ceil((hi - lo) / 5))) g.fillText(`1e${e}`, P.l - 3, Y(e) + 3);
  g.textAlign = "center";
  const [kt, ks] = niceTicks(0, n, 5);
  for (const k of kt) g.fillText(tickText(k, ks), X(k), P.b + 12);
  g.textAlign = "left";
  // the line of slope log10 |lambda| through the centroid of the samples inside the
  // linear neighbourhood (1e-7 < d < 1e-2), where the samples shrink as |lambda|^k
  const lin = d.filter(([, v]) => v > 1e-7 && v < 1e-2);
  if (lin.length >= 3 && lead > 0) {
    const kc = lin.reduce((a, [k]) => a + k, 0) / lin.length;
    const ec = lin.reduce((a, [, v]) => a + Math.log10(v), 0) / lin.length;
    const e = (k) => Math.max(lo, Math.min(hi, ec + (k - kc) * Math.log10(lead))); // formula: d_k = d_c |lambda|^(k - k_c)
    const k0 = lin[0][0];
    g.strokeStyle = "#333"; g.setLineDash([5, 4]); g.lineWidth = 1.2;
    g.beginPath(); g.moveTo(X(k0), Y(e(k0))); g.lineTo(X(n), Y(e(n))); g.stroke(); g.setLineDash([]);
    g.fillStyle = "#333"; g.font = "11px system-ui, sans-serif";
    g.fillText(`dashed: |λ|^k, |λ| = ${fmt(lead, 3)}`, P.l + 6, P.b - 6);
  }
  for (const [k, v] of d) {
    g.fillStyle = (MODES[c.orbit[k].mode] || MODES.F).color;
    g.beginPath(); g.arc(X(k), Y(Math.log10(v)), 2.5, 0, 2 * Math.PI); g.fill();
  }
}

// Right: the samples in (theta, theta') (the section's first two coordinates of the
// fixed point's mode) and the fixed point.
function strobePhase(g, c, P) {
  const mode = c.fixed ? c.fixed.point.mode : (c.orbit.length ? c.orbit[c.orbit.length - 1].mode : "P");
  const pts = c.orbit.filter((p) => p.mode === mode && mode !== "F").map((p) => p.s);
  axesBox(g, P, "θ (rad)", "θ′ (rad/s)");
  if (pts.length === 0) return;
  const xs = pts.map((s) => s[0]), ys = pts.map((s) => s[1]);
  let [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  if (x1 - x0 < 1e-6) { x0 -= 1e-3; x1 += 1e-3; }
  if (y1 - y0 < 1e-6) { y0 -= 1e-3; y1 += 1e-3; }
  const X = (x) => P.l + ((P.r - P.l) * (x - x0)) / (x1 - x0), Y = (y) => P.b - ((P.b - P.t) * (y - y0)) / (y1 - y0);
  g.fillStyle = "#444"; g.font = "10px system-ui, sans-serif"; g.textAlign = "center";
  const [xt, xs2] = niceTicks(x0, x1, 3);
  for (const v of xt) g.fillText(tickText(v, xs2), X(v), P.b + 12);
  g.textAlign = "right";
  const [yt, ys2] = niceTicks(y0, y1, 4);
  for (const v of yt) g.fillText(tickText(v, ys2), P.l - 3, Y(v) + 3);
  g.textAlign = "left";
  g.strokeStyle = "rgba(0,0,0,0.25)"; g.lineWidth = 1;
  g.beginPath(); pts.forEach((s, i) => (i ? g.lineTo(X(s[0]), Y(s[1])) : g.moveTo(X(s[0]), Y(s[1])))); g.stroke();
  g.fillStyle = (MODES[mode] || MODES.P).color;
  for (const s of pts) { g.beginPath(); g.arc(X(s[0]), Y(s[1]), 2.5, 0, 2 * Math.PI); g.fill(); }
  if (c.fixed) {
    const s = c.fixed.point.s, x = X(s[0]), y = Y(s[1]);
    g.strokeStyle = "#000"; g.lineWidth = 2;
    g.beginPath(); g.moveTo(x - 7, y - 7); g.lineTo(x + 7, y + 7); g.moveTo(x - 7, y + 7); g.lineTo(x + 7, y - 7); g.stroke();
  }
}

function axesBox(g, P, xl, yl) {
  g.strokeStyle = "#999"; g.lineWidth = 1; g.strokeRect(P.l, P.t, P.r - P.l, P.b - P.t);
  g.fillStyle = "#444"; g.font = "11px system-ui, sans-serif";
  g.fillText(xl, (P.l + P.r) / 2 - 30, P.b + 26);
  g.save(); g.translate(P.l - 34, P.b - 4); g.rotate(-Math.PI / 2); g.fillText(yl, 0, 0); g.restore();
}

// ---------- energy ----------
function drawEnergy(e) {
  const cv = $("energy"), g = cv.getContext("2d");
  g.clearRect(0, 0, cv.width, cv.height);
  if (!e) return;
  const rows = [
    ["work of the plate (in)", e.plate_work, "#009e73"],
    ["friction at C", e.friction, "#e69f00"],
    ["hinge damper", e.damper, "#cc79a7"],
    ["impacts", e.impact, "#d55e00"],
    ["change of mech. energy", e.delta_mechanical, "#0072b2"],
  ];
  const m = Math.max(...rows.map((r) => Math.abs(r[1])), 1e-12);
  const x0 = 140, w = cv.width - x0 - 50;
  g.font = "11px system-ui, sans-serif";
  rows.forEach(([label, v, c], i) => {
    const y = 6 + i * 24;
    g.fillStyle = "#444"; g.fillText(label, 0, y + 12);
    g.fillStyle = c;
    const len = (w * Math.abs(v)) / m;
    g.fillRect(x0, y + 2, Math.max(1, len), 14);
    g.fillStyle = "#222";
    g.fillText(fmt(v * 1e3, 3), x0 + len + 4, y + 13);
  });
}

// ---------- map ----------
const MP = { left: 40, right: 8, top: 8, bottom: 34 };
function mapGeom() {
  const cv = $("map"), m = lab.map;
  const th = m.theta0_rad, mu = m.mu;
  const dth = th[1] - th[0], dmu = mu[1] - mu[0];
  const t0 = th[0] - dth / 2, t1 = th[th.length - 1] + dth / 2;
  const m0 = mu[0] - dmu / 2, m1 = mu[mu.length - 1] + dmu / 2;
  const W = cv.width - MP.left - MP.right, H = cv.height - MP.top - MP.bottom;
  return {
    t0, t1, m0, m1,
    X: (t) => MP.left + (W * (t - t0)) / (t1 - t0),
    Y: (u) => MP.top + H - (H * (u - m0)) / (m1 - m0),
    T: (px) => t0 + ((px - MP.left) * (t1 - t0)) / W,
    U: (py) => m0 + ((MP.top + H - py) * (m1 - m0)) / H,
  };
}

function drawMap() {
  const cv = $("map"), g = cv.getContext("2d");
  g.clearRect(0, 0, cv.width, cv.height);
  const m = lab.map;
  if (!m) return;
  const G = mapGeom();
  const all = m.speed_mps.flat().filter((v) => v !== null).map(Math.abs).sort((a, b) => a - b);
  const vmax = all.length ? Math.max(all[Math.floor(0.98 * (all.length - 1))], 1e-9) : 1;
  m.speed_mps.forEach((row, i) => row.forEach((v, k) => {
    g.fillStyle = v === null ? "#b8b8b8" : diverging(v / vmax);
    const x0 = G.X(m.theta0_rad[k] - (m.theta0_rad[1] - m.theta0_rad[0]) / 2);
    const y0 = G.Y(m.mu[i] + (m.mu[1] - m.mu[0]) / 2);
    g.fillRect(x0, y0, G.X(m.theta0_rad[1]) - G.X(m.theta0_rad[0]) + 0.6, G.Y(m.mu[0]) - G.Y(m.mu[1]) + 0.6);
  }));
  // self-locking edge mu = tan(theta_0)
  g.save();
  g.beginPath(); g.rect(MP.left, MP.top, cv.width - MP.left - MP.right, cv.height - MP.top - MP.bottom); g.clip();
  g.strokeStyle = "#111"; g.setLineDash([5, 4]); g.lineWidth = 1.2;
  g.beginPath();
  for (let t = G.t0; t <= G.t1; t += 0.01) { const p = [G.X(t), G.Y(Math.tan(t))]; if (t === G.t0) g.moveTo(...p); else g.lineTo(...p); }
  g.stroke(); g.setLineDash([]);
  // marker at the current parameters
  const th = Number(lab.values.theta0_rad), mu = Number(lab.values.mu);
  if (Number.isFinite(th) && Number.isFinite(mu)) {
    const x = G.X(th), y = G.Y(mu);
    g.fillStyle = "#fff"; g.strokeStyle = "#000"; g.lineWidth = 2;
    g.beginPath(); g.arc(x, y, 6, 0, 2 * Math.PI); g.fill(); g.stroke();
    g.fillStyle = "#000";
    g.beginPath(); g.arc(x, y, 2, 0, 2 * Math.PI); g.fill();
  }
  g.restore();
  g.fillStyle = "#333"; g.font = "11px system-ui, sans-serif";
  for (const t of [0.2, 0.4, 0.6, 0.8]) { g.fillText(t.toFixed(1), G.X(t) - 8, cv.height - MP.bottom + 13); }
  for (const u of [0.2, 0.4, 0.6, 0.8]) { g.fillText(u.toFixed(1), MP.left - 22, G.Y(u) + 4); }
  g.fillText("spring rest angle θ₀ (rad)", MP.left + 60, cv.height - 6);
  g.save(); g.translate(11, MP.top + 150); g.rotate(-Math.PI / 2); g.fillText("friction μ", -25, 0); g.restore();
  lab.mapScale = `colour scale ±${fmt(vmax * 1e3, 2)} mm/s`;
  $("map-scale").textContent = lab.mapScale;
}

function diverging(x) {
  const c = Math.max(-1, Math.min(1, x));
  const lerp = (a, b, t) => Math.round(a + (b - a) * t);
  const [r, g, b] = c >= 0 ? [lerp(247, 178, c), lerp(247, 24, c), lerp(247, 43, c)] : [lerp(247, 33, -c), lerp(247, 102, -c), lerp(247, 172, -c)];
  return `rgb(${r},${g},${b})`;
}

function mapClick(ev) {
  if (!lab.map) return;
  const cv = $("map"), rect = cv.getBoundingClientRect();
  const px = ((ev.clientX - rect.left) * cv.width) / rect.width, py = ((ev.clientY - rect.top) * cv.height) / rect.height;
  const G = mapGeom();
  const th = G.T(px), mu = G.U(py);
  if (th < G.t0 || th > G.t1 || mu < G.m0 || mu > G.m1) return;
  for (const [k, v] of [["theta0_rad", th.toFixed(3)], ["mu", mu.toFixed(3)]]) {
    lab.values[k] = String(Number(v)); $(`f-${k}`).value = lab.values[k]; $(`s-${k}`).value = Number(v);
  }
  markPreset();
  changed();
  drawMap();
}

function mapHover(ev) {
  if (!lab.map) return;
  const cv = $("map"), rect = cv.getBoundingClientRect();
  const G = mapGeom();
  const th = G.T(((ev.clientX - rect.left) * cv.width) / rect.width), mu = G.U(((ev.clientY - rect.top) * cv.height) / rect.height);
  const m = lab.map, n = m.theta0_rad.length;
  const k = Math.round(((th - m.theta0_rad[0]) / (m.theta0_rad[n - 1] - m.theta0_rad[0])) * (n - 1));
  const i = Math.round(((mu - m.mu[0]) / (m.mu[n - 1] - m.mu[0])) * (n - 1));
  if (k < 0 || k >= n || i < 0 || i >= n) { cv.title = ""; return; }
  const v = m.speed_mps[i][k];
  cv.title = `θ₀ = ${th.toFixed(3)} rad, μ = ${mu.toFixed(3)}: ${v === null ? "falls" : `${fmt(v * 1e3, 3)} mm/s`}`;
}
