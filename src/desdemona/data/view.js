// The 3D replay of a desdemona result (desdemona.view): the machine of eq. A.7 driven by the
// trajectory's joint positions, the felt and desired specific force at the head, and the plots on one
// time cursor. World z up; one nested group per joint, in the chain's order:
//   H_world_cabin = Rz(q1) T(0, q2, 0) T(0, 0, q3) Rx(q4) Rz(q5) Ry(q6)
(function () {
  "use strict";
  const D = JSON.parse(document.getElementById("desdemona-data").textContent);
  const G = D.geometry;
  const M = D.motion;
  const C = D.classical || null;
  const t0 = M.t[0], t1 = M.t[M.t.length - 1];
  const state = { t: t0, playing: false, speed: 1, view: "orbit", classical: !!C, loop: true };

  // ---- time: linear interpolation between samples (exact at a sample time) ----
  function locate(ts, t) {
    const n = ts.length;
    if (n === 1 || t <= ts[0]) return { i: 0, w: 0 };
    if (t >= ts[n - 1]) return { i: n - 1, w: 0 };
    let lo = 0, hi = n - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (ts[mid] <= t) lo = mid; else hi = mid;
    }
    return { i: lo, w: (t - ts[lo]) / (ts[lo + 1] - ts[lo]) };
  }
  function at(values, loc) {
    const a = values[loc.i];
    if (loc.w === 0 || a === null) return a;
    const b = values[loc.i + 1];
    return b === null ? a : a + (b - a) * loc.w;
  }
  function poseOf(motion, t) {
    const loc = locate(motion.t, t);
    const q = {};
    for (const j of D.joints) q[j] = at(motion.q[j], loc);
    const vec = (v) => (v ? v.map((c) => at(c, loc)) : null);
    return { t: t, q: q, f: vec(motion.f), f_d: vec(motion.f_d) };
  }

  // ---- the scene (scene.js) ----
  const stage = document.getElementById("stage");
  const drawn = window.desdemonaScene(G, stage, state, !!C);
  const { renderer, controls, main, ghost, pose, render, resize, INSIDE_SCALE } = drawn;

  // ---- header, HUD ----
  const $ = (id) => document.getElementById(id);
  $("title").textContent = D.title;
  document.title = "desdemona: " + D.title;
  const slider = $("time");
  slider.min = t0; slider.max = t1;
  if (C) $("classical-box").hidden = false;
  function legend() {
    $("legend").innerHTML =
      '<span class="swatch" style="background:#e4572e"></span>felt f' +
      `<span class="swatch" style="background:#1e9e47"></span>desired f (1 g = ${state.view === "cabin" ? INSIDE_SCALE : 1} m)` +
      (C && state.view !== "cabin" ? '<span class="swatch" style="background:#9b59b6"></span>classical loop' : "");
  }
  const units = (j) => (D.kinds[j] === "prismatic" ? "m" : "deg");
  function hud(p) {
    const loc = locate(PL.t, p.t);
    let rows = "";
    for (const j of D.joints) {
      const v = D.kinds[j] === "prismatic" ? p.q[j] : (p.q[j] * 180) / Math.PI;
      let use = "";
      if (D.free.includes(j)) {
        const u = at(PL.use.worst[j], loc) || 0;
        const kind = PL.use.kinds[PL.use.kind[j][loc.w < 0.5 ? loc.i : loc.i + 1]];
        const colour = u >= 0.95 ? "#d62728" : u >= 0.8 ? "#e69b00" : "#2ca02c";
        use = `<span class="bar" style="width:${(Math.min(u, 1.1) * 70).toFixed(1)}px;background:${colour}"></span> ${u.toFixed(2)} ${kind}`;
      } else use = '<span class="held">held</span>';
      rows += `<tr><td>${j}</td><td align="right">${v.toFixed(D.kinds[j] === "prismatic" ? 3 : 1)} ${units(j)}</td><td>${use}</td></tr>`;
    }
    let felt = "";
    if (p.f && p.f_d && !p.f.includes(null) && !p.f_d.includes(null)) {
      const n = Math.hypot(...p.f), nd = Math.hypot(...p.f_d);
      const dot = p.f[0] * p.f_d[0] + p.f[1] * p.f_d[1] + p.f[2] * p.f_d[2];
      const angle = n > 1e-6 && nd > 1e-6 ? (Math.acos(Math.max(-1, Math.min(1, dot / (n * nd)))) * 180) / Math.PI : NaN;
      felt = `<div>|f| ${(n / G.gravity).toFixed(2)} g, desired ${(nd / G.gravity).toFixed(2)} g, apart ${isNaN(angle) ? "-" : angle.toFixed(1)} deg</div>`;
    }
    $("hud").innerHTML = `<div><b>t = ${p.t.toFixed(2)} s</b> &nbsp; joint, position, use of its limits</div><table>${rows}</table>${felt}`;
  }

  // ---- plots ----
  const PL = D.plots;
  const plots = [];
  const plotsBox = $("plots");
  const CH = ["wx [rad/s]", "wy [rad/s]", "wz [rad/s]", "fx [m/s^2]", "fy [m/s^2]", "fz [m/s^2]"];
  const JC = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b"];
  const constant = (v) => PL.t.map(() => v);
  function heading(text) { const h = document.createElement("h2"); h.textContent = text; plotsBox.appendChild(h); return h; }
  function plot(parent, title, series, columns, height, extra) {
    const el = document.createElement("div");
    el.className = "plot";
    parent.appendChild(el);
    const opts = Object.assign({
      title: title, width: 300, height: height,
      series: [{ label: "t [s]" }].concat(series),
      axes: [{ size: 28 }, { size: 48 }],
      scales: { x: { time: false }, y: { range: (u, lo, hi) => (lo === null || hi === null ? [0, 1] : hi - lo > 1e-9 ? uPlot.rangeNum(lo, hi, 0.1, true) : [lo - 1, hi + 1]) } },
      legend: { show: true, live: false },
      cursor: { drag: { x: false, y: false }, sync: { key: "desdemona" }, points: { show: false } },
    }, extra || {});
    const u = new uPlot(opts, [PL.t].concat(columns), el);
    const line = document.createElement("div");
    line.className = "cursor";
    u.over.appendChild(line);
    let dragging = false;
    const seekAt = (e) => { const v = u.posToVal(e.offsetX, "x"); if (isFinite(v)) { pause(); seek(v); } };
    u.over.addEventListener("mousedown", (e) => { dragging = true; seekAt(e); });
    u.over.addEventListener("mousemove", (e) => { if (dragging) seekAt(e); });
    window.addEventListener("mouseup", () => { dragging = false; });
    plots.push({ u: u, el: el, line: line, parent: parent });
    return u;
  }
  const solid = (label, stroke, width) => ({ label: label, stroke: stroke, width: width || 1.4 });
  const dashed = (label, stroke) => ({ label: label, stroke: stroke, width: 1.4, dash: [6, 4] });
  const faded = (label) => ({ label: label, stroke: "rgba(155,89,182,0.55)", width: 1.2 });
  const CP = C ? C.plots : null;
  const sameGrid = CP && CP.t.length === PL.t.length && CP.t.every((v, i) => v === PL.t[i]);

  if (PL.S) {
    heading("S (dashed) against S_d (solid), cabin frame" + (sameGrid ? "; classical loop faded" : ""));
    const g = document.createElement("div"); g.className = "grid2"; plotsBox.appendChild(g);
    for (let i = 0; i < 6; i++) {
      const series = [], cols = [];
      if (PL.S_d) { series.push(solid("S_d", "#222")); cols.push(PL.S_d[i]); }
      series.push(dashed("S", "#e4572e")); cols.push(PL.S[i]);
      if (sameGrid && CP.S) { series.push(faded("classical")); cols.push(CP.S[i]); }
      plot(g, CH[i], series, cols, 120);
    }
  }
  if (PL.M && PL.M_d) {
    const series = [solid("M_d", "#222"), dashed("M", "#e4572e")], cols = [PL.M_d, PL.M];
    if (sameGrid && CP.M) { series.push(faded("classical")); cols.push(CP.M); }
    plot(plotsBox, "M = |f| against M_d [m/s^2]", series, cols, 130);
  }
  if (PL.direction_deg) {
    const series = [solid("angle of f to " + (PL.S_d ? "f_d" : "cabin +z"), "#1f77b4"),
      dashed(`threshold ${D.thresholds.direction_deg.toPrecision(2)} deg`, "#d62728")];
    const cols = [PL.direction_deg, constant(D.thresholds.direction_deg)];
    if (sameGrid && CP.direction_deg) { series.push(faded("classical")); cols.push(CP.direction_deg); }
    plot(plotsBox, "felt direction error [deg]", series, cols, 130);
  }
  if (PL.rotation_deg_s) {
    const series = [], cols = [];
    for (let i = 0; i < 3; i++) { series.push(solid("|" + CH[i].slice(0, 2) + "|", JC[i])); cols.push(PL.rotation_deg_s[i]); }
    for (let i = 0; i < 3; i++) {
      series.push(dashed(`${CH[i].slice(0, 2)} threshold ${D.thresholds.rotation_deg_s[i].toPrecision(2)}`, JC[i]));
      cols.push(constant(D.thresholds.rotation_deg_s[i]));
    }
    plot(plotsBox, `felt rotation [deg/s] (${D.thresholds.vestibular} canals)`, series, cols, 140);
  }
  {
    const series = [], cols = [];
    D.free.forEach((j, i) => { series.push(solid(j, JC[D.joints.indexOf(j)] || JC[i])); cols.push(PL.use.worst[j]); });
    series.push(dashed("limit", "#d62728")); cols.push(constant(1));
    plot(plotsBox, "each joint's use of its limits (worst of position, rate, acceleration, force, power)", series, cols, 150,
      { scales: { x: { time: false }, y: { range: (u, lo, hi) => [0, Math.max(1.1, hi)] } } });
  }

  function sizePlots() {
    for (const p of plots) {
      const w = Math.max(160, p.el.parentElement.clientWidth / (p.parent.className === "grid2" ? 2 : 1) - 8);
      p.u.setSize({ width: w, height: p.u.height });
    }
    placeCursors();
  }
  function placeCursors() {
    for (const p of plots) {
      const x = p.u.valToPos(state.t, "x");
      p.line.style.left = x + "px";
      p.line.style.height = p.u.over.clientHeight + "px";
    }
  }

  // ---- the clock ----
  let lastFrame = null;
  function show() {
    const p = poseOf(M, state.t);
    pose(main, p);
    if (ghost) pose(ghost, poseOf(C.motion, state.t));
    slider.value = state.t;
    $("clock").textContent = `${state.t.toFixed(2)} / ${t1.toFixed(2)} s`;
    hud(p);
    placeCursors();
    render();
  }
  function seek(t) {
    state.t = Math.min(t1, Math.max(t0, Number(t)));
    show();
    return poseOf(M, state.t);
  }
  function play() {
    if (state.t >= t1) state.t = t0;
    state.playing = true; lastFrame = null; $("play").textContent = "Pause";
  }
  function pause() { state.playing = false; $("play").textContent = "Play"; }
  function frame(now) {
    if (state.playing) {
      if (lastFrame !== null) {
        let t = state.t + (state.speed * (now - lastFrame)) / 1000;
        if (t >= t1) { if (state.loop) t = t0; else { t = t1; pause(); } }
        state.t = t;
      }
      lastFrame = now;
      show();
    }
    requestAnimationFrame(frame);
  }
  if (controls) controls.addEventListener("change", () => { if (!state.playing) render(); });

  $("play").addEventListener("click", () => (state.playing ? pause() : play()));
  slider.addEventListener("input", () => { pause(); seek(slider.value); });
  $("speed").addEventListener("change", (e) => { state.speed = Number(e.target.value); });
  $("view").addEventListener("change", (e) => setView(e.target.value));
  $("classical").addEventListener("change", (e) => { state.classical = e.target.checked; show(); });
  $("loop").addEventListener("change", (e) => { state.loop = e.target.checked; });
  window.addEventListener("keydown", (e) => {
    if (e.key === " " && e.target === document.body) { e.preventDefault(); state.playing ? pause() : play(); }
  });
  function setView(v) {
    state.view = v; $("view").value = v;
    if (controls) controls.enabled = v !== "cabin";
    legend();
    show();
  }
  window.addEventListener("resize", () => { resize(); sizePlots(); show(); });

  resize();
  sizePlots();
  legend();
  show();
  requestAnimationFrame(frame);

  // the hook for scripts and tests (see desdemona.view)
  window.desdemonaView = {
    ready: true, webgl: !!renderer, start: t0, end: t1, samples: M.t.length, hasClassical: !!C,
    seek: (t) => seek(t),
    pose: (which) => { const p = poseOf(which === "classical" && C ? C.motion : M, state.t); return { t: p.t, q: p.q, f: p.f, f_d: p.f_d }; },
    cabinMatrix: (which) => drawn.cabinMatrix(which === "classical" ? "ghost" : "main"),
    arrows: () => drawn.arrows(),
    play: play, pause: pause,
    setSpeed: (x) => { state.speed = Math.min(4, Math.max(0.1, Number(x))); $("speed").value = String(x); return state.speed; },
    setView: setView,
    showClassical: (on) => { state.classical = !!on; $("classical").checked = !!on; show(); },
  };
})();
