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
  const MM = D.measured || null;  // a served session's measured machine
  const t0 = M.t[0], t1 = M.t[M.t.length - 1];
  const state = { t: t0, playing: false, speed: 1, view: "orbit", classical: !!C, measured: !!MM, loop: true };

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

  // ---- the scene ----
  const stage = document.getElementById("stage");
  let renderer = null;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch (err) {
    const note = document.createElement("p");
    note.textContent = "This browser gives no WebGL: the 3D view is off; the plots and the time cursor work.";
    note.style.padding = "3em 1em";
    stage.appendChild(note);
  }
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xdfe6ee);
  scene.add(new THREE.AmbientLight(0xffffff, 1.4));
  const sun = new THREE.DirectionalLight(0xffffff, 2.2);
  sun.position.set(6, -8, 14);
  scene.add(sun);

  const Ro = G.outer_ring, Ri = G.inner_ring, cab = G.cabin;
  const [tlo, thi] = G.track, [hlo, hhi] = G.heave;
  const forkZ = -(Ro + 0.35);                 // the fork's cross beam below the outer ring's bearings
  const armTop = hlo + forkZ - 0.25;          // the arm's top: clear of the fork at the lowest heave
  const armH = 0.45, armW = 0.7;
  const ground = armTop - armH - 1.6;
  const armLo = tlo - 1.0, armHi = thi + 1.0;

  function material(color, opacity) {
    const m = new THREE.MeshLambertMaterial({ color: color });
    if (opacity < 1) { m.transparent = true; m.opacity = opacity; m.depthWrite = false; }
    return m;
  }
  function box(sx, sy, sz, x, y, z, mat) {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz), mat);
    mesh.position.set(x, y, z);
    return mesh;
  }
  function rod(from, to, radius, mat) {  // a cylinder between two points of its group
    const a = new THREE.Vector3(...from), b = new THREE.Vector3(...to);
    const mesh = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, a.distanceTo(b), 16), mat);
    mesh.position.copy(a).add(b).multiplyScalar(0.5);
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), b.clone().sub(a).normalize());
    return mesh;
  }
  function ring(radius, tube, mat) { return new THREE.Mesh(new THREE.TorusGeometry(radius, tube, 14, 96), mat); }
  // an arrow from the head: a shaft and a cone along the group's +y, turned and scaled by setArrow
  function arrow(color, opacity) {
    const a = new THREE.Group();
    const mat = material(color, opacity);
    a.shaft = new THREE.Mesh(new THREE.CylinderGeometry(0.03, 0.03, 1, 12), mat);
    a.cone = new THREE.Mesh(new THREE.CylinderGeometry(0, 0.085, 0.22, 16), mat);
    a.add(a.shaft, a.cone);
    a.position.set(...G.head_offset);
    return a;
  }
  // One machine; ghost = the classical loop's, faded ("measured": the measured machine's, ghosted in
  // teal). Returns the six joint groups and the arrows.
  function machine(ghost) {
    const op = ghost ? 0.28 : 1;
    const col = ghost === "measured"
      ? { arm: 0x5fa8a0, carriage: 0x5fa8a0, outer: 0x2a9d8f, inner: 0x2a9d8f, cabin: 0x8fd1c8, head: 0x8fd1c8 }
      : ghost
      ? { arm: 0x8a8fa0, carriage: 0x8a8fa0, outer: 0x9b7fc9, inner: 0x9b7fc9, cabin: 0xb9a6e0, head: 0xb9a6e0 }
      : { arm: 0x6b7a8f, carriage: 0x39424e, outer: 0xd9822b, inner: 0x2b6cd9, cabin: 0xf2f2f2, head: 0xe0b48f };
    const root = new THREE.Group();
    const yaw = new THREE.Group(), track = new THREE.Group(), heave = new THREE.Group();
    const outer = new THREE.Group(), inner = new THREE.Group(), cabin = new THREE.Group();
    root.add(yaw); yaw.add(track); track.add(heave); heave.add(outer); outer.add(inner); inner.add(cabin);
    // arm (q1): a beam along its y axis, rails on top, a hub on the yaw axis
    const armMat = material(col.arm, op);
    yaw.add(box(armW, armHi - armLo, armH, 0, 0.5 * (armLo + armHi), armTop - 0.5 * armH, armMat));
    yaw.add(box(0.08, armHi - armLo, 0.08, -0.22, 0.5 * (armLo + armHi), armTop + 0.04, material(0x444444, op)));
    yaw.add(box(0.08, armHi - armLo, 0.08, 0.22, 0.5 * (armLo + armHi), armTop + 0.04, material(0x444444, op)));
    yaw.add(rod([0, 0, armTop - armH - 0.05], [0, 0, armTop + 0.15], 0.55, armMat));
    for (const y of [tlo, thi]) yaw.add(box(armW + 0.1, 0.12, 0.3, 0, y + Math.sign(y) * 0.75, armTop + 0.15, material(0xc0392b, op)));
    // track carriage (q2) with the heave guide
    const carMat = material(col.carriage, op);
    track.add(box(1.3, 1.5, 0.3, 0, 0, armTop + 0.23, carMat));
    track.add(box(0.5, 0.5, 0.9, 0, 0, armTop + 0.8, carMat));
    // heave (q3): the column in its guide and the fork that holds the outer ring's bearings (x axis)
    const forkMat = material(0x555d68, op);
    heave.add(rod([0, 0, armTop + 0.4 - hhi + hlo], [0, 0, forkZ], 0.16, forkMat));
    heave.add(box(2 * Ro + 0.5, 0.25, 0.25, 0, 0, forkZ, forkMat));
    for (const s of [-1, 1]) {
      heave.add(box(0.22, 0.25, -forkZ + 0.12, s * (Ro + 0.25), 0, 0.5 * forkZ + 0.06, forkMat));
      heave.add(rod([s * Ro, 0, 0], [s * (Ro + 0.25), 0, 0], 0.06, forkMat));
    }
    // outer gimbal (q4 about x): a ring in the xz plane, bearings at +-x (fork) and +-z (inner ring)
    const outerRing = ring(Ro, 0.07, material(col.outer, op));
    outerRing.rotation.x = Math.PI / 2;
    outer.add(outerRing);
    for (const s of [-1, 1]) outer.add(rod([0, 0, s * Ri], [0, 0, s * Ro], 0.05, material(col.outer, op)));
    // inner gimbal (q5 about z): a ring in the yz plane, bearings at +-z (outer ring) and +-y (cabin)
    const innerRing = ring(Ri, 0.06, material(col.inner, op));
    innerRing.rotation.y = Math.PI / 2;
    inner.add(innerRing);
    for (const s of [-1, 1]) inner.add(rod([0, s * 0.5 * cab[1], 0], [0, s * Ri, 0], 0.05, material(col.inner, op)));
    // cabin (q6 about y): a see-through shell, its front (+y) marked, the occupant's seat, body and head
    const shell = new THREE.Mesh(new THREE.BoxGeometry(...cab),
      new THREE.MeshLambertMaterial({ color: col.cabin, transparent: true, opacity: ghost ? 0.12 : 0.22,
        side: THREE.DoubleSide, depthWrite: false }));
    cabin.add(shell);
    cabin.add(box(cab[0] * 0.8, 0.03, cab[2] * 0.5, 0, 0.5 * cab[1], 0.05 * cab[2], material(ghost ? col.cabin : 0x3d7ec9, ghost ? op : 0.45)));
    cabin.add(box(cab[0], cab[1], 0.05, 0, 0, -0.5 * cab[2], material(ghost ? col.cabin : 0x8d99a6, op)));
    const h = G.head_offset;
    const occupant = new THREE.Group();
    occupant.add(box(0.55, 0.12, 0.8, h[0], h[1] - 0.32, h[2] - 0.45, material(ghost ? col.cabin : 0x2c3e50, op)));
    occupant.add(box(0.55, 0.6, 0.12, h[0], h[1] - 0.05, h[2] - 0.85, material(ghost ? col.cabin : 0x2c3e50, op)));
    occupant.add(rod([h[0], h[1] - 0.15, h[2] - 0.8], [h[0], h[1] - 0.15, h[2] - 0.15], 0.17, material(ghost ? col.head : 0x5d6d7e, op)));
    const head = new THREE.Mesh(new THREE.SphereGeometry(0.12, 24, 16), material(col.head, op));
    head.position.set(...h);
    occupant.add(head);
    occupant.add(box(0.05, 0.08, 0.03, h[0], h[1] + 0.12, h[2] + 0.01, material(0x333333, op)));  // the nose: forward
    cabin.add(occupant);
    const felt = arrow(ghost ? 0x9b59b6 : 0xe4572e, ghost ? 0.5 : 1);
    cabin.add(felt);
    let desired = null;
    if (!ghost) { desired = arrow(0x1e9e47, 1); cabin.add(desired); }
    scene.add(root);
    return { root: root, joints: [yaw, track, heave, outer, inner, cabin], cabin: cabin, occupant: occupant,
      felt: felt, desired: desired };
  }

  // the static base: ground, the yaw column's foundation, the track's ends drawn by the arm
  const grid = new THREE.GridHelper(2 * (armHi + 3), 2 * Math.round(armHi + 3), 0x9aa5b1, 0xc4ccd4);
  grid.rotation.x = Math.PI / 2;
  grid.position.z = ground;
  scene.add(grid);
  scene.add(rod([0, 0, ground], [0, 0, armTop - armH - 0.05], 0.7, material(0x7f8c8d, 1)));
  const main = machine(false);
  const ghost = C ? machine(true) : null;
  const shadow = MM ? machine("measured") : null;

  const UP = new THREE.Vector3(0, 1, 0), ARROW_PER_G = 1.0, INSIDE_SCALE = 0.25;  // 1 g = 1 m (0.25 m inside)
  function setArrow(a, f) {
    if (!f || f.some((c) => c === null)) { a.visible = false; return; }
    const v = new THREE.Vector3(f[0], f[1], f[2]);
    const n = v.length();
    if (n < 1e-6) { a.visible = false; return; }
    a.visible = true;
    a.quaternion.setFromUnitVectors(UP, v.divideScalar(n));
    // inside the cabin, smaller and in front of the occupant, in sight
    const cabinView = state.view === "cabin";
    a.scale.setScalar(cabinView ? INSIDE_SCALE : 1);
    a.position.set(G.head_offset[0], G.head_offset[1] + (cabinView ? 0.3 * cab[1] : 0), G.head_offset[2] - (cabinView ? 0.3 : 0));
    const length = Math.max(0.25, (ARROW_PER_G * n) / G.gravity), head = 0.22;
    a.shaft.scale.y = length - head;
    a.shaft.position.y = 0.5 * (length - head);
    a.cone.position.y = length - 0.5 * head;
  }
  function pose(m, p) {  // drive one machine: each group moves by its own joint only
    const [yaw, track, heave, outer, inner, cabin] = m.joints;
    yaw.rotation.z = p.q.yaw;
    track.position.y = p.q.track;
    heave.position.z = p.q.heave;
    outer.rotation.x = p.q.outer_gimbal;
    inner.rotation.z = p.q.inner_gimbal;
    cabin.rotation.y = p.q.cabin;
    setArrow(m.felt, p.f);
    if (m.desired) setArrow(m.desired, p.f_d);
  }

  // cameras: an orbit about the machine (or following the cabin) and one inside the cabin
  const camera = new THREE.PerspectiveCamera(42, 1, 0.05, 300);
  camera.up.set(0, 0, 1);
  const reach = Math.max(Math.abs(armLo), Math.abs(armHi));
  camera.position.set(1.35 * reach + 3, -1.6 * reach - 3, 0.9 * reach + 2);
  const inside = new THREE.PerspectiveCamera(80, 1, 0.02, 300);
  inside.rotation.x = Math.PI / 2 - 0.25;   // looking along cabin +y (forward), a little down; cabin +z up
  inside.position.set(G.head_offset[0], G.head_offset[1] - 0.42 * cab[1], G.head_offset[2] + 0.35);
  main.cabin.add(inside);
  let controls = null;
  if (renderer) {
    stage.insertBefore(renderer.domElement, stage.firstChild);
    controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.target.set(0, 0, 0.5 * (armTop + 0));
    controls.update();
  }
  const lastCabin = new THREE.Vector3();

  function resize() {
    if (!renderer) return;
    const w = stage.clientWidth, h = Math.max(stage.clientHeight, 200);
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(w, h);
    camera.aspect = inside.aspect = w / h;
    camera.updateProjectionMatrix();
    inside.updateProjectionMatrix();
  }

  let rendering = false;  // controls.update() below fires "change", which renders: once is enough
  function render() {
    if (!renderer || rendering) return;
    rendering = true;
    scene.updateMatrixWorld(true);
    const here = new THREE.Vector3().setFromMatrixPosition(main.cabin.matrixWorld);
    if (state.view === "follow") {
      camera.position.add(here.clone().sub(lastCabin));
      controls.target.copy(here);
      controls.update();
    }
    lastCabin.copy(here);
    main.occupant.visible = state.view !== "cabin";
    if (ghost) ghost.root.visible = state.classical && state.view !== "cabin";
    if (shadow) shadow.root.visible = state.measured && state.view !== "cabin";
    renderer.render(scene, state.view === "cabin" ? inside : camera);
    rendering = false;
  }

  // ---- header, HUD ----
  const $ = (id) => document.getElementById(id);
  $("title").textContent = D.title;
  document.title = "desdemona: " + D.title;
  const slider = $("time");
  slider.min = t0; slider.max = t1;
  if (C) $("classical-box").hidden = false;
  if (MM) $("measured-box").hidden = false;
  function legend() {
    $("legend").innerHTML =
      '<span class="swatch" style="background:#e4572e"></span>felt f' +
      `<span class="swatch" style="background:#1e9e47"></span>desired f (1 g = ${state.view === "cabin" ? INSIDE_SCALE : 1} m)` +
      (C && state.view !== "cabin" ? '<span class="swatch" style="background:#9b59b6"></span>classical loop' : "") +
      (MM && state.view !== "cabin" ? '<span class="swatch" style="background:#2a9d8f"></span>measured machine' : "");
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

  if (MM) {
    const series = [], cols = [];
    D.free.forEach((j, i) => { series.push(solid(j + (D.kinds[j] === "prismatic" ? " [m]" : " [rad]"), JC[D.joints.indexOf(j)] || JC[i])); cols.push(MM.plots.error[j]); });
    plot(plotsBox, "tracking error: the measured machine less the command", series, cols, 140);
    plot(plotsBox, "use of the service's tracking tolerance (1 = a fault)", [solid("use", "#2a9d8f"), dashed("fault", "#d62728")],
      [MM.plots.use, constant(1)], 120, { scales: { x: { time: false }, y: { range: (u, lo, hi) => [0, Math.max(1.1, hi)] } } });
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
    if (shadow) pose(shadow, poseOf(MM.motion, state.t));
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
  $("measured").addEventListener("change", (e) => { state.measured = e.target.checked; show(); });
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
    ready: true, webgl: !!renderer, start: t0, end: t1, samples: M.t.length, hasClassical: !!C, hasMeasured: !!MM,
    seek: (t) => seek(t),
    pose: (which) => {
      const motion = which === "classical" && C ? C.motion : which === "measured" && MM ? MM.motion : M;
      const p = poseOf(motion, state.t);
      return { t: p.t, q: p.q, f: p.f, f_d: p.f_d };
    },
    cabinMatrix: (which) => {
      const g = (which === "classical" && ghost ? ghost : which === "measured" && shadow ? shadow : main).cabin;
      scene.updateMatrixWorld(true);
      const e = g.matrixWorld.elements;  // column-major
      return [0, 1, 2, 3].flatMap((r) => [0, 1, 2, 3].map((c) => e[4 * c + r]));
    },
    arrows: () => {  // the drawn arrows' world directions (their +y), null where hidden
      scene.updateMatrixWorld(true);
      const dir = (a) => (a && a.visible ? new THREE.Vector3().setFromMatrixColumn(a.matrixWorld, 1).normalize().toArray() : null);
      return { felt: dir(main.felt), desired: dir(main.desired) };
    },
    play: play, pause: pause,
    setSpeed: (x) => { state.speed = Math.min(4, Math.max(0.1, Number(x))); $("speed").value = String(x); return state.speed; },
    setView: setView,
    showClassical: (on) => { state.classical = !!on; $("classical").checked = !!on; show(); },
    showMeasured: (on) => { state.measured = !!on; $("measured").checked = !!on; show(); return shadow ? shadow.root.visible : false; },
  };
})();
