// The stick lab's drawing: the animation, the mode timeline and x_C(t), the energy
// budget and the speed map (with its click). Shares the globals of page.js.

// ---------- animation ----------
function tick(now) {
  const run = lab.run;
  if (run && run.frames.t_s.length > 0) {
    const ts = run.frames.t_s;
    const tEnd = ts[ts.length - 1];
    if (lab.playing && lab.lastWall !== null) {
      lab.simT += ((now - lab.lastWall) / 1000) * Number($("speed").value);
      if (lab.simT > tEnd) lab.simT = 0;
    }
    lab.frame = frameAt(run, lab.simT);
    drawAnim();
    drawCursor();
  }
  lab.lastWall = now;
  requestAnimationFrame(tick);
}

function state(run, i) {
  const f = run.frames;
  return {
    t: f.t_s[i], mode: f.mode[i], th: f.theta_rad[i], x: f.x_c_m[i], z: f.z_c_m[i],
    zp: f.plate_z_m[i], fx: f.f_x_n[i], fz: f.f_z_n[i],
  };
}

function drawAnim() {
  const cv = $("anim"), g = cv.getContext("2d");
  const W = cv.width, H = cv.height;
  const run = lab.run, sc = run.scene;
  const s = 190 / sc.length_m; // px per metre
  // vertical motion of plate and C magnified, at most 20 x and to at most 40 px of plate travel
  const ampPx = sc.plate_amplitude_m * s;
  const E = $("magnify").checked ? Math.max(1, Math.min(20, Math.floor(40 / Math.max(ampPx, 1e-9)))) : 1;
  const y0 = H - 34 - E * ampPx;
  const cur = state(run, lab.frame);
  const camX = cur.x;
  const X = (x) => W * 0.42 + (x - camX) * s;
  const Y = (z) => y0 - z * s * E;
  g.clearRect(0, 0, W, H);
  // plate
  const yp = Y(cur.zp);
  g.fillStyle = "#cbd5e0";
  g.fillRect(0, yp, W, H - yp);
  g.strokeStyle = "#718096";
  g.lineWidth = 1;
  g.beginPath(); g.moveTo(0, yp); g.lineTo(W, yp); g.stroke();
  const tick = niceStep(W / s / 12);
  g.fillStyle = "#4a5568";
  g.font = "11px system-ui, sans-serif";
  for (let k = Math.floor((camX - W / s) / tick); k <= Math.ceil((camX + W / s) / tick); k++) {
    const px = X(k * tick);
    if (px < -2 || px > W + 2) continue;
    g.beginPath(); g.moveTo(px, yp); g.lineTo(px, yp + (k % 5 === 0 ? 12 : 6)); g.stroke();
  }
  g.fillText(`plate ticks every ${fmtLen(tick)}; the camera follows C`, 8, H - 8);
  // the comparison run, grey, at the same time
  if (lab.cmp) {
    const j = frameAt(lab.cmp, cur.t);
    if (j >= 0) {
      const c = state(lab.cmp, j);
      drawRod(g, X(c.x), Y(c.z), c.th, s * lab.cmp.scene.length_m, "rgba(120,120,120,0.45)", 7);
    }
  }
  // trail of C over the last three drive cycles
  const back = Math.max(1, Math.round((3 * sc.period_s) / run.frames.dt_s));
  g.strokeStyle = "rgba(49,130,206,0.55)";
  g.lineWidth = 1.5;
  g.beginPath();
  for (let i = Math.max(0, lab.frame - back); i <= lab.frame; i++) {
    const st = state(run, i);
    const px = X(st.x), py = Y(st.z);
    if (i === Math.max(0, lab.frame - back)) g.moveTo(px, py); else g.lineTo(px, py);
  }
  g.stroke();
  // the rod, coloured by mode
  const cx = X(cur.x), cy = Y(cur.z);
  const mode = MODES[cur.mode] || MODES.F;
  // friction cone and contact force at C
  if (cur.mode !== "F") {
    const a = Math.atan(sc.mu), r = 130; // as long as the longest force arrow
    g.fillStyle = "rgba(72,187,120,0.13)";
    g.strokeStyle = "rgba(47,133,90,0.5)";
    g.beginPath(); g.moveTo(cx, cy);
    g.lineTo(cx - r * Math.sin(a), cy - r * Math.cos(a));
    g.lineTo(cx + r * Math.sin(a), cy - r * Math.cos(a));
    g.closePath(); g.fill(); g.stroke();
    const f = Math.hypot(cur.fx, cur.fz) / sc.weight_n;
    const len = Math.min(130, 150 * f); // 150 px per weight m g, at most the cone
    if (len > 1) arrow(g, cx, cy, cx + (len * cur.fx) / (f * sc.weight_n), cy - (len * cur.fz) / (f * sc.weight_n), "#c53030");
  }
  drawRod(g, cx, cy, cur.th, s * sc.length_m, mode.color, 9);
  g.fillStyle = "#222";
  g.beginPath(); g.arc(cx, cy, 3.5, 0, 2 * Math.PI); g.fill();
  g.font = "12px system-ui, sans-serif";
  g.fillText("C", cx - 14, cy + 4);
  const px = cx + s * sc.length_m * Math.sin(cur.th), py = cy - s * sc.length_m * Math.cos(cur.th);
  g.fillText("P", px + 12, py - 8);
  // labels
  g.font = "bold 15px system-ui, sans-serif";
  g.fillStyle = mode.color;
  g.fillText(mode.name, 10, 22);
  g.font = "12px system-ui, sans-serif";
  g.fillStyle = "#444";
  g.fillText(`θ = ${cur.th.toFixed(3)} rad   x_C = ${(cur.x * 1e3).toFixed(2)} mm`, 10, 40);
  if (cur.mode !== "F") {
    g.fillStyle = "#c53030";
    g.fillText(`force on C: ${fmt(cur.fx, 3)} N across, ${fmt(cur.fz, 3)} N up (cone: |F_x| ≤ μ F_z)`, 10, 56);
  }
  if (E > 1) { g.fillStyle = "#888"; g.textAlign = "right"; g.fillText(`vertical motion of plate and C drawn ${E} x larger`, W - 10, 22); g.textAlign = "left"; }
  $("magnify-label").textContent = `vertical motion x${E > 1 ? E : 20}`;
  $("clock").textContent = `t = ${cur.t.toFixed(3)} s  (frame ${lab.frame + 1}/${lab.frameCount})`;
}

function drawRod(g, cx, cy, th, len, color, r) {
  const px = cx + len * Math.sin(th), py = cy - len * Math.cos(th);
  g.strokeStyle = color; g.lineWidth = 4; g.lineCap = "round";
  g.beginPath(); g.moveTo(cx, cy); g.lineTo(px, py); g.stroke();
  g.fillStyle = color;
  g.beginPath(); g.arc(px, py, r, 0, 2 * Math.PI); g.fill();
}

function arrow(g, x0, y0, x1, y1, color) {
  const a = Math.atan2(y1 - y0, x1 - x0);
  g.strokeStyle = color; g.fillStyle = color; g.lineWidth = 2.5;
  g.beginPath(); g.moveTo(x0, y0); g.lineTo(x1, y1); g.stroke();
  g.beginPath(); g.moveTo(x1, y1);
  g.lineTo(x1 - 9 * Math.cos(a - 0.4), y1 - 9 * Math.sin(a - 0.4));
  g.lineTo(x1 - 9 * Math.cos(a + 0.4), y1 - 9 * Math.sin(a + 0.4));
  g.closePath(); g.fill();
}

function niceStep(x) {
  const e = Math.pow(10, Math.floor(Math.log10(x)));
  for (const m of [1, 2, 5, 10]) if (m * e >= x) return m * e;
  return 10 * e;
}
const fmtLen = (m) => (m >= 0.01 ? `${fmt(m * 100, 3)} cm` : `${fmt(m * 1000, 3)} mm`);

// ---------- timeline: mode strip and x_C(t) ----------
const TL = { left: 64, right: 10, top: 6, strip: 16, bottom: 22 };
function drawTimeline() {
  const cv = $("timeline"), g = cv.getContext("2d");
  const W = cv.width, H = cv.height;
  g.clearRect(0, 0, W, H);
  const run = lab.run;
  if (!run) return;
  const f = run.frames, n = f.t_s.length;
  if (n === 0) return;
  const tEnd = Math.max(f.t_s[n - 1], lab.cmp ? lab.cmp.frames.t_s[lab.cmp.frames.t_s.length - 1] : 0);
  const X = (t) => TL.left + ((W - TL.left - TL.right) * t) / (tEnd || 1);
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
  const runs = [run, lab.cmp].filter(Boolean);
  let lo = Infinity, hi = -Infinity;
  for (const r of runs) for (const x of r.frames.x_c_m) { lo = Math.min(lo, x); hi = Math.max(hi, x); }
  if (hi - lo < 1e-6) { hi += 5e-4; lo -= 5e-4; }
  const y0 = TL.top + TL.strip + 8, y1 = H - TL.bottom;
  const Y = (x) => y1 - ((y1 - y0) * (x - lo)) / (hi - lo);
  g.strokeStyle = "#ddd"; g.lineWidth = 1;
  g.strokeRect(TL.left, y0, W - TL.left - TL.right, y1 - y0);
  runs.forEach((r, k) => {
    g.strokeStyle = k === 0 ? "#2d3748" : "rgba(120,120,120,0.8)";
    g.lineWidth = k === 0 ? 1.6 : 1.6;
    g.setLineDash(k === 0 ? [] : [5, 3]);
    g.beginPath();
    r.frames.t_s.forEach((t, i) => { const p = [X(t), Y(r.frames.x_c_m[i])]; if (i) g.lineTo(...p); else g.moveTo(...p); });
    g.stroke();
  });
  g.setLineDash([]);
  g.fillStyle = "#444";
  g.fillText(`${fmt(hi * 1e3, 3)}`, 6, y0 + 9);
  g.fillText(`${fmt(lo * 1e3, 3)}`, 6, y1);
  g.fillText("x_C (mm)", 6, (y0 + y1) / 2 + 4);
  g.fillText("0", TL.left - 3, H - 6);
  g.fillText(`${fmt(tEnd, 3)} s`, W - TL.right - 34, H - 6);
  g.fillText(lab.cmp ? "time  (solid: this run, dashed: kept run; click to jump)" : "time  (click to jump)", TL.left + 150, H - 6);
  lab.tlImage = g.getImageData(0, 0, W, H);
  lab.tlEnd = tEnd;
}

function drawCursor() {
  if (!lab.tlImage) return;
  const cv = $("timeline"), g = cv.getContext("2d");
  g.putImageData(lab.tlImage, 0, 0);
  const x = TL.left + ((cv.width - TL.left - TL.right) * lab.simT) / (lab.tlEnd || 1);
  g.strokeStyle = "#e53e3e"; g.lineWidth = 1.5;
  g.beginPath(); g.moveTo(x, TL.top); g.lineTo(x, cv.height - TL.bottom); g.stroke();
}

// ---------- energy ----------
function drawEnergy(e) {
  const cv = $("energy"), g = cv.getContext("2d");
  g.clearRect(0, 0, cv.width, cv.height);
  if (!e) return;
  const rows = [
    ["work of the plate (in)", e.plate_work, "#2f855a"],
    ["friction at C", e.friction, "#dd6b20"],
    ["hinge damper", e.damper, "#805ad5"],
    ["impacts", e.impact, "#c53030"],
    ["change of mech. energy", e.delta_mechanical, "#3182ce"],
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
  const n = m.theta0_rad.length;
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
    lab.values[k] = v; $(`f-${k}`).value = v; $(`s-${k}`).value = v;
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

