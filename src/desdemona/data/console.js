// The operator's console of a served session (desdemona.service.console): the machine of eq. A.7 as
// commanded (solid) and as measured (faded, where the machine reports its State), the felt and desired
// specific force at the head, the felt direction and rotation against their thresholds, each joint's use
// of its limits, the session's status, latency and drops, the host's stream; the operator's buttons.
// Frames come from the service's own host over a WebSocket (/stream), 25 a second.
(function () {
  "use strict";
  const D = JSON.parse(document.getElementById("desdemona-data").textContent);
  const $ = (id) => document.getElementById(id);
  const state = { view: "orbit", classical: false };
  const drawn = window.desdemonaScene(D.geometry, $("stage"), state, true);
  const WINDOW_S = 20, KEPT = 200;  // seconds plotted; frames kept for scripts (window.consoleState.drawn)
  const live = { ready: false, connected: false, ended: null, frames: 0, frame: null, drawn: [], replies: [] };
  window.consoleState = live;

  $("title").textContent = "desdemona: " + D.title;
  document.title = "desdemona console: " + D.title;
  $("legend").innerHTML = '<span class="swatch" style="background:#e4572e"></span>felt f' +
    '<span class="swatch" style="background:#1e9e47"></span>desired f (1 g = 1 m)' +
    '<span class="swatch" style="background:#9b59b6"></span>measured machine';

  // ---- the stream ----
  const token = new URLSearchParams(window.location.search).get("token");
  const url = (window.location.protocol === "https:" ? "wss://" : "ws://") + window.location.host + "/stream" +
    (token ? "?token=" + encodeURIComponent(token) : "");
  const socket = new WebSocket(url);
  socket.addEventListener("open", () => { live.connected = true; setStatus("connected", ""); });
  socket.addEventListener("message", (event) => {
    const m = JSON.parse(event.data);
    if ("ended" in m) { ended(m.ended || "the service stopped"); return; }
    if (m.accepted || m.refused) {
      live.replies.push(m);
      $("said").textContent = m.accepted ? `sent: ${m.accepted}` : `refused: ${m.refused}`;
      return;
    }
    receive(m);
  });
  socket.addEventListener("close", (event) => {
    live.connected = false;
    live.closed = { code: event.code, reason: event.reason };
    ended(live.ended || "the service stopped (its stream closed)");
  });
  socket.addEventListener("error", () => {});  // the close that follows says it

  function ended(why) {
    if (live.ended) return;
    live.ended = why;
    $("banner").textContent = "The session is over: " + why + ". The buttons are off; the machine is no longer served from here.";
    $("banner").classList.add("open");
    setStatus("ended", "ended");
    for (const b of document.querySelectorAll("header button")) b.disabled = true;
    closeConfirm();
  }
  function setStatus(text, cls) { const s = $("status"); s.textContent = text; s.className = cls; }

  // ---- the buttons: an emergency stop at once, the others once confirmed ----
  const QUESTIONS = {
    pause: "Pause: hold the present cue (plan on the host's last message, the host no longer followed) until Resume?",
    park: "Park: brake the machine to rest within its limits and hold until Resume?",
    resume: "Resume: follow the host again, from where the machine stands (it will move)?",
    reset: "Reset: clear the emergency stop (the machine takes setpoints again; Resume to move)?",
  };
  let pending = null;
  function send(action) {
    if (live.ended || socket.readyState !== WebSocket.OPEN) return false;
    socket.send(JSON.stringify({ command: action }));
    return true;
  }
  function closeConfirm() { pending = null; $("confirm").classList.remove("open"); }
  for (const b of document.querySelectorAll("header button[data-action]")) {
    b.addEventListener("click", () => {
      const action = b.dataset.action;
      if (action === "emergency stop") { closeConfirm(); send(action); return; }
      pending = action;
      $("question").textContent = QUESTIONS[action];
      $("confirm").classList.add("open");
    });
  }
  $("yes").addEventListener("click", () => { if (pending) send(pending); closeConfirm(); });
  $("no").addEventListener("click", closeConfirm);

  // ---- the side panel ----
  const side = $("side");
  function section(title) {
    const h = document.createElement("h2"); h.textContent = title; side.appendChild(h);
    const d = document.createElement("div"); side.appendChild(d); return d;
  }
  const sessionBox = section("session");
  const feltBox = section("felt at the head (cabin frame)");
  const jointBox = section("joints: commanded, measured, use of their limits (1 = at a limit)");
  const hostBox = section("the host's stream");
  const plotBox = section(`the last ${WINDOW_S} s`);
  const fmt = (x, d) => (x === null || x === undefined ? "-" : x.toFixed(d));
  const norm = (v) => (v ? Math.hypot(v[0], v[1], v[2]) : null);
  const G = D.geometry.gravity;

  const series = { t: [], M: [], M_d: [], dir: [], latency: [] };
  const plots = [];
  function plot(title, labels, colours, height, range) {
    const el = document.createElement("div"); plotBox.appendChild(el);
    const u = new uPlot({
      title: title, width: 360, height: height,
      series: [{ label: "t [s]" }].concat(labels.map((l, i) => ({ label: l, stroke: colours[i], width: 1.4, dash: i === 1 ? [6, 4] : undefined }))),
      axes: [{ size: 28 }, { size: 48 }], legend: { show: true, live: false }, cursor: { show: false },
      scales: { x: { time: false }, y: { range: range } },
    }, [[], ...labels.map(() => [])], el);
    plots.push({ u: u, el: el });
    return u;
  }
  const positive = (u, lo, hi) => [0, Math.max(hi === null ? 1 : hi * 1.1, 1e-3)];
  const forcePlot = plot("|f| felt and desired [m/s^2]", ["felt", "desired"], ["#e4572e", "#1e9e47"], 120, positive);
  const dirPlot = plot("felt direction error [deg]", ["error", "threshold"], ["#1f77b4", "#d62728"], 110, positive);
  const latPlot = plot("latency [ms]", ["host message to setpoint"], ["#555"], 100, positive);

  function sessionHtml(m) {
    return `<table>
      <tr><td>time</td><td>${m.t.toFixed(2)} s</td><td>command</td><td>${m.command}${m.reason ? " (" + m.reason + ")" : ""}</td></tr>
      <tr><td>operator</td><td>${m.paused || "-"}</td><td>machine</td><td>${m.machine_status || "no State"}${m.tracking_use === null ? "" : ", tracking " + m.tracking_use.toFixed(2)}</td></tr>
      <tr><td>latency</td><td>${fmt(m.latency_ms, 2)} ms</td><td>compute</td><td>${fmt(m.compute_ms, 2)} ms</td></tr>
      <tr><td>message age</td><td>${fmt(m.age_ms, 1)} ms</td><td>received, dropped</td><td>${m.received}, ${m.dropped}</td></tr></table>`;
  }
  function feltHtml(m) {
    const th = D.thresholds;
    const over = (x, limit) => (x !== null && x >= limit ? ' class="over"' : "");
    let rot = "";
    for (let i = 0; i < 3; i++) {
      const x = m.rotation_deg_s[i];
      rot += `<td${over(x, th.rotation_deg_s[i])}>${"xyz"[i]} ${fmt(x, 2)} / ${th.rotation_deg_s[i].toPrecision(2)}</td>`;
    }
    const vec = (v) => (v ? v.map((x) => fmt(x, 2)).join(", ") : "-");
    return `<table>
      <tr><td>f felt</td><td>${vec(m.f)} m/s^2</td><td>|f| ${fmt(norm(m.f) / G, 3)} g</td></tr>
      <tr><td>f desired</td><td>${vec(m.f_d)} m/s^2</td><td>|f_d| ${m.f_d ? fmt(norm(m.f_d) / G, 3) : "-"} g</td></tr>
      <tr><td>direction error</td><td${over(m.direction_deg, th.direction_deg)}>${fmt(m.direction_deg, 2)} deg</td><td>threshold ${th.direction_deg.toPrecision(2)} deg</td></tr>
      </table><table><tr><td>felt rotation [deg/s] / threshold (${th.vestibular})</td>${rot}</tr></table>`;
  }
  function jointHtml(m) {
    let rows = "";
    for (const j of D.joints) {
      const angle = D.kinds[j] !== "prismatic";
      const v = (x) => (x === null || x === undefined ? "-" : angle ? ((x * 180) / Math.PI).toFixed(2) + " deg" : x.toFixed(3) + " m");
      let use = '<span class="held">held</span>';
      if (m.use[j]) {
        const u = m.use[j].use || 0;
        const colour = u >= 0.95 ? "#d62728" : u >= 0.8 ? "#e69b00" : "#2ca02c";
        use = `<span class="bar" style="width:${(Math.min(u, 1.1) * 70).toFixed(1)}px;background:${colour}"></span> ${u.toFixed(2)} ${m.use[j].kind}`;
      }
      rows += `<tr><td>${j}</td><td align="right">${v(m.q[j])}</td><td align="right">${m.measured ? v(m.measured.q[j]) : "-"}</td><td>${use}</td></tr>`;
    }
    const when = m.measured && m.measured.applied_time !== null
      ? `measured: where the machine was at t = ${m.measured.applied_time.toFixed(2)} s (its newest State)` : "measured: no State";
    return `<table>${rows}</table><div>${when}</div>`;
  }
  function hostHtml(m) {
    if (!m.host) return "no host message yet";
    return `sequence ${m.host.sequence}, its time ${m.host.time.toFixed(3)} s: ${m.host.values.map((x) => fmt(x, 3)).join(", ")}`;
  }

  // every frame goes into the plots' series; the newest is drawn at the browser's next paint, so that a
  // slow browser skips frames rather than falls behind the session
  let pending_frame = null;
  function receive(m) {
    live.frames += 1;
    series.t.push(m.t); series.M.push(norm(m.f)); series.M_d.push(norm(m.f_d));
    series.dir.push(m.direction_deg); series.latency.push(m.latency_ms);
    while (series.t.length && series.t[0] < m.t - WINDOW_S) for (const k in series) series[k].shift();
    if (pending_frame === null) requestAnimationFrame(() => { const f = pending_frame; pending_frame = null; show(f); });
    pending_frame = m;
  }
  function show(m) {
    live.frame = m;
    const p = { t: m.t, q: m.q, f: m.f, f_d: m.f_d };
    drawn.pose(drawn.main, p);
    state.classical = !!m.measured;
    if (m.measured) drawn.pose(drawn.ghost, { t: m.t, q: m.measured.q, f: null, f_d: null });
    drawn.render();
    live.drawn.push({ t: m.t, q: m.q, measured: m.measured ? m.measured.q : null });
    if (live.drawn.length > KEPT) live.drawn.shift();
    if (!live.ended) setStatus(m.status + (m.paused ? " (" + m.paused + ")" : ""), m.status);
    $("clock").textContent = `t = ${m.t.toFixed(2)} s`;
    sessionBox.innerHTML = sessionHtml(m);
    feltBox.innerHTML = feltHtml(m);
    jointBox.innerHTML = jointHtml(m);
    hostBox.textContent = hostHtml(m);
    const th = series.t.map(() => D.thresholds.direction_deg);
    forcePlot.setData([series.t, series.M, series.M_d]);
    dirPlot.setData([series.t, series.dir, th]);
    latPlot.setData([series.t, series.latency]);
  }

  function resize() {
    drawn.resize();
    for (const p of plots) p.u.setSize({ width: Math.max(200, side.clientWidth - 20), height: p.u.height });
    drawn.render();
  }
  window.addEventListener("resize", resize);
  if (drawn.controls) drawn.controls.addEventListener("change", () => drawn.render());
  resize();
  // for scripts and tests: what was drawn (the cabins' poses) and the state of the stream
  live.cabinMatrix = (which) => drawn.cabinMatrix(which === "measured" ? "ghost" : "main");
  live.arrows = () => drawn.arrows();
  live.webgl = !!drawn.renderer;
  live.ready = true;
})();
