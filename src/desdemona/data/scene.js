// The machine of eq. A.7 drawn with three.js, shared by the result's replay (view.js) and the live
// console (console.js): one nested group per joint, in the chain's order, world z up,
//   H_world_cabin = Rz(q1) T(0, q2, 0) T(0, 0, q3) Rx(q4) Rz(q5) Ry(q6)
// the felt and desired specific force as arrows at the head, an orbit camera and one inside the cabin.
// desdemonaScene(G, stage, state, ghost): G the machine's sizes (desdemona.results.view.geometry), stage
// the element drawn into, state {view, classical} read at each render, ghost whether a second, faded
// machine is drawn (the classical loop's, or the measured machine's).
window.desdemonaScene = function (G, stage, state, withGhost) {
  "use strict";
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
  // One machine; ghost = the classical loop's, faded. Returns the six joint groups and the arrows.
  function machine(ghost) {
    const op = ghost ? 0.28 : 1;
    const col = ghost
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
  const ghost = withGhost ? machine(true) : null;

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
    renderer.render(scene, state.view === "cabin" ? inside : camera);
    rendering = false;
  }

  function cabinMatrix(which) {  // a drawn cabin's H_world_cabin, 16 numbers row by row
    const g = (which === "ghost" && ghost ? ghost : main).cabin;
    scene.updateMatrixWorld(true);
    const e = g.matrixWorld.elements;  // column-major
    return [0, 1, 2, 3].flatMap((r) => [0, 1, 2, 3].map((c) => e[4 * c + r]));
  }
  function arrows() {  // the drawn arrows' world directions (their +y), null where hidden
    scene.updateMatrixWorld(true);
    const dir = (a) => (a && a.visible ? new THREE.Vector3().setFromMatrixColumn(a.matrixWorld, 1).normalize().toArray() : null);
    return { felt: dir(main.felt), desired: dir(main.desired) };
  }
  return { renderer: renderer, controls: controls, main: main, ghost: ghost, pose: pose, render: render,
    resize: resize, cabinMatrix: cabinMatrix, arrows: arrows, INSIDE_SCALE: INSIDE_SCALE };
};
