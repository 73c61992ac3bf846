// camkin studio: draws what the server (or a report's inlined data) computed. No numerics of
// its own beyond placing points on the screen and evaluating the force quadratic the server
// states (see answer.rs, DynamicsOut).
"use strict";
(function () {
  const REPORT = window.CAMKIN_REPORT || null;
  // in a notebook: the widget's kernel answers the requests in place of the server
  // ({name, toml, post(what, body) -> Promise<{status, text}>})
  const BRIDGE = window.CAMKIN_BRIDGE || null;
  const $ = (id) => document.getElementById(id);
  const PLOTS = [
    ["lift", "#1f77b4"], ["velocity", "#ff7f0e"], ["acceleration", "#2ca02c"],
    ["jerk", "#9467bd"], ["pressure_angle", "#8c564b"], ["radius_of_curvature", "#17becf"],
  ];
  const S = {
    result: null, toml: "", name: "", index: 0, playing: false, compare: null,
    rpm: null, inflight: false, pending: null, timings: [], lastError: null,
    drag: null, nodes: null, hoverPlot: null, view: null,
  };
  window.studio = S; // for tests and the curious: the state on screen
  // where node i is on the screen (client pixels), for a test's mouse
  S.nodeScreen = (i) => {
    const r = S.result, f = r.frames[S.index];
    const q = S.view.tx(camToWorld(f, (S.nodes || r.nodes)[i]));
    const rect = $("drawing").getBoundingClientRect();
    return [rect.left + q[0], rect.top + q[1]];
  };
  S.idle = () => !S.inflight && !S.pending && !S.drag && !S.comparing && (REPORT || !S.result || S.compareFor === S.toml);

  // ---------- numbers for people ----------
  const { fmt, fitCanvas } = window.CamkinChart;
  const { camToWorld, worldToCam, legendItems, drawLegend, drawShapes, drawContact, drawSense } =
    window.CamkinScene;
  function drawPlot(p) { window.CamkinChart.draw(p, S.result, S.result ? angleAt(S.index) : null); }
  function angleAt(i) { return S.result.angles_deg[i]; }
  // a value below its series' resolution is rounding: shown as 0
  function snap(s, v) { return s.resolution && v !== null && Math.abs(v) < s.resolution ? 0 : v; }

  // ---------- network ----------
  async function post(path, body) {
    if (BRIDGE) {
      const a = await BRIDGE.post(path.replace(/^api\//, ""), body);
      if (a.status !== 200) {
        let e;
        try { e = JSON.parse(a.text).error; } catch (_) { e = { message: a.text }; }
        e.status = a.status;
        throw e;
      }
      return { json: async () => JSON.parse(a.text), blob: async () => new Blob([a.text]) };
    }
    const r = await fetch(path, { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) });
    const ct = r.headers.get("Content-Type") || "";
    if (!r.ok) {
      const e = ct.includes("json") ? (await r.json()).error : { message: await r.text() };
      e.status = r.status;
      throw e;
    }
    return r;
  }

  function setStatus(text, bad) {
    const s = $("status");
    s.textContent = text;
    s.className = bad ? "bad" : "";
  }

  // Analysis requests are coalesced: while one is in flight, only the newest edit waits.
  function requestAnalysis(body) {
    if (REPORT) return;
    if (S.inflight) { S.pending = body; return; }
    S.inflight = true;
    const t0 = performance.now();
    post("api/analyze", body)
      .then((r) => r.json())
      .then((ans) => {
        const t1 = performance.now();
        show(ans.result, ans.toml, body.nodes !== undefined);
        const t2 = performance.now();
        const timing = { server_ms: ans.result.server_ms, network_ms: t1 - t0, total_ms: t2 - t0 };
        S.timings.push(timing);
        if (S.timings.length > 200) S.timings.shift();
        setStatus(`${ans.result.simulated ? "simulation of" : "exact analysis of"} ${ans.result.angles_deg.length} ${ans.result.simulated ? "output steps" : "angles"}: ${fmt(timing.server_ms, 3)} ms ${BRIDGE ? "in the kernel" : "on the server"}, ${fmt(timing.total_ms, 3)} ms from the edit to the screen`);
        clearError();
        if (S.compareFor !== undefined && S.compareFor !== ans.toml) runCompare();
      })
      .catch((e) => showError(e))
      .finally(() => {
        S.inflight = false;
        if (S.pending) { const b = S.pending; S.pending = null; requestAnalysis(b); }
      });
  }

  function clearError() {
    S.lastError = null;
    $("error").hidden = true;
    $("editor").classList.remove("bad");
  }

  function showError(e) {
    S.lastError = e;
    const box = $("error");
    box.hidden = false;
    box.textContent = "";
    if (e.line) {
      const where = document.createElement("span");
      where.className = "where";
      where.textContent = `line ${e.line}, column ${e.column}`;
      where.title = "go there";
      where.onclick = () => goTo(e.line, e.column);
      box.appendChild(where);
      box.appendChild(document.createTextNode(": "));
    }
    box.appendChild(document.createTextNode(e.message || String(e)));
    $("editor").classList.add("bad");
    setStatus(S.result ? "the last valid result stays on screen until the error is mended" : "error", true);
  }

  function goTo(line, col) {
    const ed = $("editor");
    const lines = ed.value.split("\n");
    let at = 0;
    for (let i = 0; i < line - 1 && i < lines.length; i++) at += lines[i].length + 1;
    at += Math.max(0, col - 1);
    ed.focus();
    ed.setSelectionRange(at, at + 1);
  }

  // ---------- showing a result ----------
  function show(result, toml, fromDrag) {
    S.result = result;
    S.toml = toml;
    if (!S.drag) S.nodes = result.nodes.map((p) => p.slice());
    if ($("editor").value !== toml && (fromDrag || document.activeElement !== $("editor"))) {
      $("editor").value = toml;
    }
    const n = result.angles_deg.length;
    const slider = $("angle");
    if (+slider.max !== n - 1) {
      const a = S.index * (+slider.max + 1 > 0 ? 360 / (+slider.max + 1) : 0);
      slider.max = n - 1;
      S.index = Math.round(a / result.step_deg) % n;
      slider.value = S.index;
    }
    S.index = Math.min(S.index, n - 1);
    $("title").textContent = `studio — ${result.name}`;
    $("file-name").textContent = `${result.name}, lengths in ${result.length_unit}`;
    $("drag-hint").textContent = result.system
      ? "A system of bodies, joints and contacts: the slider turns its first driver; edit the file to change it."
      : result.nodes_editable
        ? "Drag a blue node to reshape the cam; the plots follow at once."
        : "This profile is not a spline with inline points: edit the file to change it.";
    $("compare-panel").hidden = !!result.system || (REPORT && !REPORT.compare);
    $("checks-panel").hidden = !!result.system && !result.simulated;
    $("checks-title").textContent = result.simulated ? "Impacts" : "Design checks";
    $("plots-sub").textContent = result.simulated
      ? "simulated: the contact method's rows imposed on the equations of motion; hover for values, click to set the angle"
      : "exact, by the contact method; hover for values, click to set the angle";
    $("angle").setAttribute("aria-label", result.system ? "driver angle" : "cam angle");
    $("plots-title").textContent = result.system ? "Over one revolution of the driver" : "Over one revolution";
    buildPlots();
    drawChecks();
    setupDynamics();
    redraw();
  }

  function redraw() {
    if (!S.result) return;
    drawMechanism();
    drawValues();
    for (const p of S.plots || []) drawPlot(p);
    drawCompare();
    drawForce();
    drawLubrication();
    drawGearLoads();
    $("angle-readout").textContent = `${fmt(angleAt(S.index), 4)}°`;
  }

  // ---------- the drawing ----------
  function drawMechanism() {
    const c = $("drawing");
    c.style.height = Math.round(c.clientWidth * 440 / 520) + "px";
    const { g, w, h } = fitCanvas(c);
    const r = S.result, f = r.frames[S.index];
    const [x0, y0, x1, y1] = r.extent;
    const pad = 0.06 * Math.max(x1 - x0, y1 - y0);
    // the legend's band at the top is kept clear of the drawing
    const band = legendItems(r).length * 15 + 14, hh = h - band;
    const k = Math.min(w / (x1 - x0 + 2 * pad), hh / (y1 - y0 + 2 * pad));
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    const view = { k, tx: (p) => [w / 2 + (p[0] - cx) * k, band + hh / 2 - (p[1] - cy) * k] };
    view.back = (sx, sy) => [cx + (sx - w / 2) / k, cy - (sy - band - hh / 2) / k];
    S.view = view;
    g.clearRect(0, 0, w, h);
    g.fillStyle = "#fff";
    g.fillRect(0, 0, w, h);
    g.lineJoin = "round";
    if (!r.system) drawCam(g, r, f, view, x0, y0, x1, y1);
    // the follower, from the server's model of it (a system: every body and contact)
    drawShapes(g, r, f, view, k);
    if (!r.system) drawContact(g, r, f, view, Math.max(x1 - x0, y1 - y0));
    drawSense(g, r, view, Math.max(x1 - x0, y1 - y0));
    // a scale bar
    const size = Math.max(x1 - x0, y1 - y0);
    const bar = Math.pow(10, Math.floor(Math.log10(size / 4)));
    g.strokeStyle = "#444"; g.lineWidth = 2;
    g.beginPath(); g.moveTo(12, h - 14); g.lineTo(12 + bar * k, h - 14); g.stroke();
    g.fillStyle = "#444"; g.font = "12px DejaVu Sans, sans-serif";
    g.fillText(`${fmt(bar)} ${r.length_unit}`, 16 + bar * k, h - 10);
    g.fillText(`${r.system ? "driver" : "cam"} angle ${fmt(angleAt(S.index), 4)}°`, 12, 18);
    drawLegend(g, r, w);
  }

  function drawCam(g, r, f, view, x0, y0, x1, y1) {
    // the profile, turned with the cam
    g.beginPath();
    r.profile.forEach((p, i) => {
      const [sx, sy] = view.tx(camToWorld(f, p));
      if (i === 0) g.moveTo(sx, sy); else g.lineTo(sx, sy);
    });
    g.closePath();
    g.fillStyle = "rgba(31,119,180,0.07)";
    g.fill();
    g.strokeStyle = "#1f77b4";
    g.lineWidth = 2;
    g.stroke();
    // stretches the follower cannot follow
    for (const ch of r.checks) {
      for (const st of ch.stretches) {
        g.beginPath();
        st.forEach((p, i) => {
          const [sx, sy] = view.tx(camToWorld(f, p));
          if (i === 0) g.moveTo(sx, sy); else g.lineTo(sx, sy);
        });
        g.strokeStyle = "#d62728";
        g.lineWidth = 5;
        g.stroke();
      }
    }
    // the cam's axis and its frame's x axis
    const [px, py] = view.tx(r.pivot);
    const size = Math.max(x1 - x0, y1 - y0);
    const ax = view.tx(camToWorld(f, [0.12 * size, 0]));
    g.strokeStyle = "#1f77b4";
    g.lineWidth = 1;
    g.beginPath(); g.moveTo(px, py); g.lineTo(ax[0], ax[1]); g.stroke();
    g.strokeStyle = "#3c3c3c";
    g.beginPath(); g.arc(px, py, 4, 0, 2 * Math.PI); g.stroke();
    // nodes
    const nodes = S.nodes || r.nodes;
    nodes.forEach((p, i) => {
      const [sx, sy] = view.tx(camToWorld(f, p));
      g.beginPath();
      g.arc(sx, sy, r.nodes_editable ? 5 : 3, 0, 2 * Math.PI);
      g.fillStyle = S.drag && S.drag.i === i ? "#ff7f0e" : "#1f77b4";
      g.fill();
      if (r.nodes_editable) { g.strokeStyle = "#fff"; g.lineWidth = 1.5; g.stroke(); }
    });
  }

  function readout(v, top) { return v !== null && top > 0 && Math.abs(v) <= 1e-9 * top ? 0 : v; }
  function drawValues() {
    const r = S.result, i = S.index;
    if (S.tops !== r) {
      // each series' largest magnitude, and the drawing's, once per result
      S.tops = r;
      S.top = r.series.map((s) => s.values.reduce((m, v) => (v !== null && isFinite(v) ? Math.max(m, Math.abs(v)) : m), 0));
      S.extentTop = Math.max(...r.extent.map(Math.abs));
    }
    const rows = r.series.map((s, k) => `<tr><td>${s.label}</td><td class="num">${fmt(readout(snap(s, s.values[i]), S.top[k]), 6)}</td><td>${s.unit}</td></tr>`);
    const f = r.frames[i];
    if (f.contact) rows.push(`<tr><td>contact point</td><td class="num">(${fmt(readout(f.contact[0], S.extentTop), 5)}, ${fmt(readout(f.contact[1], S.extentTop), 5)})</td><td>${r.length_unit}</td></tr>`);
    $("values").innerHTML = rows.join("");
  }

  // angles in runs of consecutive steps: [[first, last], …]
  function ranges(angles, step) {
    const out = [];
    for (const a of angles) {
      const last = out[out.length - 1];
      if (last && Math.abs(a - last[1] - step) < 1e-6 * step) last[1] = a; else out.push([a, a]);
    }
    return out;
  }

  function drawChecks() {
    const r = S.result;
    $("checks").innerHTML = "";
    for (const ch of r.checks) {
      const li = document.createElement("li");
      li.className = ch.ok ? "ok" : "bad";
      li.dataset.kind = ch.kind;
      let text = ch.message;
      if (!ch.ok && ch.angles_deg.length) {
        const runs = ranges(ch.angles_deg, r.step_deg);
        const shown = runs.slice(0, 4).map(([a, b]) => (a === b ? `${fmt(a, 4)}°` : `${fmt(a, 4)}°–${fmt(b, 4)}°`)).join(", ");
        text += ` — at ${shown}${runs.length > 4 ? ", …" : ""}`;
        li.title = "click to go to the first angle";
        li.style.cursor = "pointer";
        li.onclick = () => setIndex(Math.round(ch.angles_deg[0] / r.step_deg) % r.frames.length);
      }
      li.textContent = text;
      $("checks").appendChild(li);
    }
    for (const e of r.events || []) {
      const li = document.createElement("li");
      li.className = "ok";
      li.textContent = e.message;
      li.title = "click to go to its angle";
      li.style.cursor = "pointer";
      li.onclick = () => setIndex(Math.round(e.angle_deg / r.step_deg) % r.frames.length);
      $("checks").appendChild(li);
    }
    $("warnings").innerHTML = "";
    for (const w of r.warnings) {
      const li = document.createElement("li");
      li.textContent = w.message;
      $("warnings").appendChild(li);
    }
  }

  // ---------- plots ----------
  function buildPlots() {
    const box = $("plots");
    // a cam's six plots, or a system's bodies' coordinates: one plot per series, rebuilt when
    // the series change (another file)
    const keys = S.result.series.map((x) => x.key);
    if (S.plots && S.plots.map((p) => p.key).join("\n") !== keys.join("\n")) {
      box.innerHTML = "";
      S.plots = null;
    }
    if (!S.plots) {
      const colors = PLOTS.map(([, c]) => c);
      S.plots = keys.map((key, i) => [key, (PLOTS.find(([k]) => k === key) || [key, colors[i % colors.length]])[1]]).map(([key, color]) => {
        const c = document.createElement("canvas");
        c.height = 118;
        c.dataset.key = key;
        box.appendChild(c);
        const p = { canvas: c, key, color };
        attachHover(p);
        return p;
      });
    }
    for (const p of S.plots) {
      const s = S.result.series.find((x) => x.key === p.key);
      p.series = [{ values: s.values, color: p.color, label: s.label, resolution: s.resolution }];
      p.title = s.label;
      p.unit = s.unit;
      p.clip = p.key === "radius_of_curvature" || p.key === "jerk";
      p.minSpan = p.key === "pressure_angle" ? 2 : 0;
      // a series that is zero but for rounding is drawn on a span that shows it as zero
      if (s.resolution) p.minSpan = Math.max(p.minSpan, 1e6 * s.resolution);
    }
  }

  function attachHover(p) {
    const tip = $("tooltip");
    const at = (ev) => {
      if (!p.geom || !S.result) return null;
      const rect = p.canvas.getBoundingClientRect();
      const mx = ev.clientX - rect.left;
      const { L, R, w, x } = p.geom;
      const [x0, x1] = p.xr || [0, 360];
      const a = x0 + ((mx - L) / (w - L - R)) * (x1 - x0);
      if (a < x0 || a > x1) return null;
      let best = 0;
      for (let i = 1; i < x.length; i++) if (Math.abs(x[i] - a) < Math.abs(x[best] - a)) best = i;
      return best;
    };
    p.canvas.addEventListener("mousemove", (ev) => {
      const i = at(ev);
      if (i === null) { tip.hidden = true; return; }
      const lines = [p.xr ? `${p.xname} ${fmt(p.geom.x[i], 5)} ${p.xunit}` : `cam angle ${fmt(p.geom.x[i], 5)}°`];
      for (const s of p.series) lines.push(`${s.label}: ${fmt(snap(s, s.values[i]), 6)}${p.unit ? " " + p.unit : ""}`);
      if (p.extra) lines.push(...p.extra(i));
      tip.textContent = lines.join("\n");
      tip.hidden = false;
      tip.style.left = ev.clientX + 14 + "px";
      tip.style.top = ev.clientY + 10 + "px";
    });
    p.canvas.addEventListener("mouseleave", () => { tip.hidden = true; });
    p.canvas.addEventListener("click", (ev) => {
      const i = at(ev);
      if (i === null || !S.result || p.xr) return;
      setIndex(Math.round(p.geom.x[i] / S.result.step_deg) % S.result.frames.length);
    });
  }

  // ---------- compare ----------
  // The study follows every edit: a study of another text is never shown as this one's.
  function runCompare() {
    if (REPORT) return;
    // a system has no interpolation study
    if (S.result && S.result.system) { S.compare = null; S.compareFor = S.toml; return; }
    if (S.comparing) { S.compareAgain = true; return; }
    S.comparing = true;
    const n = Math.round(+$("compare-n").value);
    const toml = S.toml;
    post("api/compare", { toml, nodes: [n], step_deg: S.result ? S.result.step_deg : 0.5 })
      .then((r) => r.json())
      .then((c) => { S.compare = c; S.compareFor = toml; drawCompare(); })
      .catch((e) => { S.compare = null; S.compareFor = toml; $("compare-summary").textContent = e.message; drawCompare(); })
      .finally(() => {
        S.comparing = false;
        if (S.compareAgain || S.compareFor !== S.toml) { S.compareAgain = false; if (S.compareFor !== S.toml) runCompare(); }
      });
  }

  function drawCompare() {
    const c = S.compare;
    if (!c) return;
    if (!REPORT && S.compareFor !== S.toml) {
      $("compare-summary").textContent = "updating for the edited mechanism…";
      return;
    }
    if (c.refused) {
      $("compare-summary").textContent = c.refused;
      for (const id of ["compare-acc", "compare-err"]) { const { g, w, h } = fitCanvas($(id)); g.clearRect(0, 0, w, h); }
      return;
    }
    const run = c.runs[0];
    $("compare-summary").textContent = `N = ${run.nodes}: largest error ${fmt(100 * run.max_rel_error, 3)} % of the peak acceleration, mean ${fmt(100 * run.mean_rel_error, 3)} %`;
    if (!S.cmpPlots) {
      S.cmpPlots = [{ canvas: $("compare-acc") }, { canvas: $("compare-err") }];
      S.cmpPlots.forEach(attachHover);
    }
    const [pa, pe] = S.cmpPlots;
    Object.assign(pa, {
      x: c.angles_deg, title: "acceleration", unit: c.unit, legend: true, noMarks: true,
      series: [{ values: c.exact, color: "#2ca02c", label: "exact" }, { values: run.acceleration, color: "#ff7f0e", label: `interpolated, N = ${run.nodes}`, dash: [4, 3] }],
    });
    Object.assign(pe, {
      x: c.angles_deg, title: "relative error |a_N − a| / max|a|", unit: "1", log: true, noMarks: true,
      series: [{ values: run.rel_error, color: "#d62728", label: "error" }],
    });
    drawPlot(pa);
    drawPlot(pe);
  }

  // ---------- dynamics ----------
  function setupDynamics() {
    const d = S.result.dynamics;
    $("dynamics-panel").hidden = !d;
    if (!d) return;
    const top = Math.max(2 * d.rpm, d.jump_rpm ? 1.5 * d.jump_rpm : 0);
    const slider = $("rpm");
    slider.max = Math.ceil(top);
    if (S.rpm === null) S.rpm = d.rpm;
    slider.value = S.rpm;
    if (!S.forcePlot) {
      S.forcePlot = { canvas: $("force") };
      attachHover(S.forcePlot);
    }
    if (!S.lubPlot) {
      S.lubPlot = { canvas: $("lubrication") };
      attachHover(S.lubPlot);
    }
  }

  // the file's [lubrication] at the file's speed: λ on a log scale, shaded by regime
  const REGIME_SHADES = ["rgba(214,39,40,0.16)", "rgba(240,180,40,0.18)", "rgba(44,160,44,0.14)"];
  const REGIME_NAMES = ["boundary", "mixed", "full film"];
  function drawLubrication() {
    const d = S.result && S.result.dynamics;
    const l = d && d.lubrication;
    $("lubrication-box").hidden = !l;
    if (!l || !S.lubPlot) return;
    const parts = [];
    if (l.min_lambda) parts.push(`λ min ${fmt(l.min_lambda[0], 4)} at ${fmt(l.min_lambda[1], 4)}° (${REGIME_NAMES[l.min_lambda[0] < 1 ? 0 : l.min_lambda[0] < 3 ? 1 : 2]})`);
    if (l.max_flash_k) parts.push(`flash temperature max ${fmt(l.max_flash_k[0], 4)} K at ${fmt(l.max_flash_k[1], 4)}°`);
    parts.push(l.entrainment_reversals_deg.length
      ? `entrainment reverses at ${l.entrainment_reversals_deg.map((a) => fmt(a, 5) + "°").join(", ")}`
      : "entrainment never reverses");
    parts.push(`friction ${fmt(l.friction[0], 4)} W mean (${fmt(l.friction[1], 4)} N·m on the camshaft)`);
    const sum = $("lubrication-summary");
    sum.textContent = `Lubrication at the file's ${fmt(d.rpm, 4)} rpm: ${parts.join("; ")}.`;
    sum.className = l.min_lambda && l.min_lambda[0] < 1 ? "bad" : "";
    // a log scale where λ spans more than a decade
    const ls = l.lambda.filter((v) => v !== null && v > 0);
    const wide = ls.length > 0 && Math.max(...ls) > 10 * Math.min(...ls);
    Object.assign(S.lubPlot, {
      title: "λ = h_min / σ, shaded by regime: red boundary (λ < 1), amber mixed, green full film (λ ≥ 3)", unit: "", log: wide, noMarks: true,
      series: [{ values: l.lambda, color: "#1f77b4", label: "λ" }],
      shade: (g, X, Y, t, b) => {
        const x = S.result.angles_deg, step = S.result.step_deg;
        l.regime.forEach((r, i) => {
          if (r === null) return;
          g.fillStyle = REGIME_SHADES[r];
          g.fillRect(X(x[i] - step / 2), t, Math.max(1, X(step) - X(0)), b - t);
        });
      },
    });
    drawPlot(S.lubPlot);
  }

  // ---------- a gear pair's loads along its path of contact ----------
  // the driver's radius of the contact drawn (the first contact), for the cursor
  function contactRadius() {
    const f = S.result.frames[S.index];
    if (!f || !f.contact) return null;
    return Math.hypot(f.contact[0] - S.result.pivot[0], f.contact[1] - S.result.pivot[1]);
  }

  function drawGearLoads() {
    const G = S.result && S.result.gear_loads;
    $("gear-panel").hidden = !G;
    if (!G) return;
    if (!S.gearPlots) {
      S.gearPlots = ["gear-hertz", "gear-sliding", "gear-lambda"].map((id) => ({ canvas: $(id) }));
      S.gearPlots.forEach(attachHover);
    }
    const u = G.unit;
    const xr = [G.radius[0], G.radius[G.radius.length - 1]];
    const common = { x: G.radius, xr, xunit: u, xname: "driver's contact radius", noMarks: true, cursor: contactRadius };
    const parts = [
      `torque ${fmt(G.torque, 4)} N·m on the driver, normal force ${fmt(G.normal_force, 4)} N, face width ${fmt(G.face_width, 4)} ${u}, contact ratio ${fmt(G.contact_ratio, 4)}`,
    ];
    if (G.max_hertz) parts.push(`Hertz max ${fmt(G.max_hertz[0], 4)} MPa at radius ${fmt(G.max_hertz[1], 4)} ${u}, ${fmt(G.pitch[1], 4)} MPa at the pitch point (radius ${fmt(G.pitch[0], 4)} ${u})`);
    if (G.min_lambda) parts.push(`λ min ${fmt(G.min_lambda[0], 3)} at radius ${fmt(G.min_lambda[1], 4)} ${u} (${REGIME_NAMES[G.min_lambda[0] < 1 ? 0 : G.min_lambda[0] < 3 ? 1 : 2]})`);
    if (G.max_flash_k) parts.push(`flash temperature max ${fmt(G.max_flash_k[0], 4)} K at radius ${fmt(G.max_flash_k[1], 4)} ${u}`);
    const sum = $("gear-summary");
    sum.textContent = `At the file's ${fmt(S.result.rpm, 4)} rpm: ${parts.join("; ")}.`;
    sum.className = G.min_lambda && G.min_lambda[0] < 1 ? "bad" : "";
    const pairs = (i) => [`${G.pairs[i]} pair${G.pairs[i] === 1 ? "" : "s"} in contact, ${fmt(G.load[i], 4)} N on this one`];
    const [ph, ps, pl] = S.gearPlots;
    Object.assign(ph, common, {
      title: "Hertz pressure (shaded: one pair carries the whole load; elsewhere two share it)", unit: "MPa", extra: pairs,
      series: [{ values: G.hertz_mpa, color: "#d62728", label: "Hertz" }],
      shade: (g, X, Y, t, b) => {
        // where one pair carries the whole load
        g.fillStyle = "rgba(31,119,180,0.08)";
        G.pairs.forEach((n, i) => {
          if (n !== 1 || i + 1 >= G.radius.length) return;
          g.fillRect(X(G.radius[i]), t, Math.max(1, X(G.radius[i + 1]) - X(G.radius[i])), b - t);
        });
      },
    });
    Object.assign(ps, common, {
      title: "specific sliding", unit: "", legend: true,
      series: [
        { values: G.specific_sliding[0], color: "#1f77b4", label: "driver (w1 − w2)/w1" },
        { values: G.specific_sliding[1], color: "#ff7f0e", label: "driven (w2 − w1)/w2", dash: [5, 3] },
      ],
    });
    drawPlot(ph);
    drawPlot(ps);
    pl.canvas.hidden = !G.lambda;
    if (G.lambda) {
      Object.assign(pl, common, {
        title: "λ = h_min / σ: red boundary (λ < 1), amber mixed, green full film (λ ≥ 3)", unit: "",
        series: [{ values: G.lambda, color: "#1f77b4", label: "λ" }],
        extra: (i) => G.flash_temperature_k && G.flash_temperature_k[i] !== null ? [`flash temperature ${fmt(G.flash_temperature_k[i], 4)} K`] : [],
        shade: (g, X, Y, t, b) => {
          G.regime.forEach((r, i) => {
            if (r === null || i + 1 >= G.radius.length) return;
            g.fillStyle = REGIME_SHADES[r];
            g.fillRect(X(G.radius[i]), t, Math.max(1, X(G.radius[i + 1]) - X(G.radius[i])), b - t);
          });
        },
      });
      drawPlot(pl);
    }
  }

  function forceAt(rpm) {
    const w = (rpm * Math.PI) / 30;
    return S.result.dynamics.coefficients.map((c) => (c ? (c[0] * w * w + c[1] * w + c[2]) / c[3] : null));
  }

  function drawForce() {
    const d = S.result && S.result.dynamics;
    if (!d || !S.forcePlot) return;
    const rpm = S.rpm;
    const f = forceAt(rpm);
    let min = Infinity, at = 0;
    f.forEach((v, i) => { if (v !== null && v < min) { min = v; at = i; } });
    $("rpm-readout").textContent = `${fmt(rpm, 4)} rpm (the file: ${fmt(d.rpm, 4)} rpm)`;
    const sum = $("dynamics-summary");
    const jump = d.jump_rpm ? `The follower first leaves the cam at ${fmt(d.jump_rpm, 4)} rpm, at ${fmt(d.jump_angle_deg, 4)}°` : "The contact holds at every speed";
    if (min < 0) {
      sum.textContent = `At ${fmt(rpm, 4)} rpm the contact force falls below zero (lowest ${fmt(min, 4)} N at ${fmt(angleAt(at), 4)}°): the follower jumps. ${jump}.`;
      sum.className = "bad";
    } else {
      sum.textContent = `At ${fmt(rpm, 4)} rpm the contact holds: lowest force ${fmt(min, 4)} N at ${fmt(angleAt(at), 4)}°. ${jump}.`;
      sum.className = "";
    }
    Object.assign(S.forcePlot, {
      title: `contact force at ${fmt(rpm, 4)} rpm`, unit: d.unit, noMarks: true,
      series: [{ values: f, color: "#1f77b4", label: "contact force" }],
      shade: (g, X, Y, t, b) => {
        g.fillStyle = "rgba(214,39,40,0.18)";
        const x = S.result.angles_deg, step = S.result.step_deg;
        f.forEach((v, i) => { if (v !== null && v < 0) g.fillRect(X(x[i] - step / 2), t, Math.max(1, X(step) - X(0)), b - t); });
      },
    });
    drawPlot(S.forcePlot);
  }

  // ---------- interaction ----------
  function setIndex(i) {
    S.index = i;
    $("angle").value = i;
    redraw();
  }

  function nodeAt(sx, sy) {
    const r = S.result;
    if (!r || !r.nodes_editable || !S.view) return -1;
    const f = r.frames[S.index];
    let best = -1, bd = 10;
    (S.nodes || r.nodes).forEach((p, i) => {
      const q = S.view.tx(camToWorld(f, p));
      const d = Math.hypot(q[0] - sx, q[1] - sy);
      if (d < bd) { bd = d; best = i; }
    });
    return best;
  }

  function canvasXY(ev) {
    const rect = $("drawing").getBoundingClientRect();
    return [ev.clientX - rect.left, ev.clientY - rect.top];
  }

  function roundTo(x, size) {
    // four significant places of the cam's size: a node to 1e-4 of it, as a drawing is read
    const d = Math.max(0, 4 - Math.floor(Math.log10(size)));
    return Number(x.toFixed(Math.min(d, 10)));
  }

  function setupDrawing() {
    const c = $("drawing");
    c.addEventListener("pointerdown", (ev) => {
      if (REPORT) return;
      const [sx, sy] = canvasXY(ev);
      const i = nodeAt(sx, sy);
      if (i < 0) return;
      S.drag = { i };
      S.playing = false; $("play").textContent = "▶";
      c.setPointerCapture(ev.pointerId);
      c.className = "grabbing";
      ev.preventDefault();
    });
    c.addEventListener("pointermove", (ev) => {
      const [sx, sy] = canvasXY(ev);
      if (!S.drag) { c.className = !REPORT && nodeAt(sx, sy) >= 0 ? "grab" : ""; return; }
      const r = S.result, f = r.frames[S.index];
      const [x0, y0, x1, y1] = r.extent, size = Math.max(x1 - x0, y1 - y0);
      const p = worldToCam(f, S.view.back(sx, sy));
      S.nodes[S.drag.i] = [roundTo(p[0], size), roundTo(p[1], size)];
      drawMechanism();
      requestAnalysis({ toml: S.toml, nodes: S.nodes.map((q) => q.slice()), step_deg: r.step_deg });
    });
    const end = () => {
      if (!S.drag) return;
      S.drag = null;
      c.className = "";
      drawMechanism();
    };
    c.addEventListener("pointerup", end);
    c.addEventListener("pointercancel", end);
  }

  function setupControls() {
    $("angle").addEventListener("input", (e) => setIndex(+e.target.value));
    $("play").addEventListener("click", () => {
      S.playing = !S.playing;
      $("play").textContent = S.playing ? "❚❚" : "▶";
      if (S.playing) requestAnimationFrame(tick);
    });
    document.addEventListener("keydown", (e) => {
      if (e.target === $("editor") || e.target.tagName === "INPUT") return;
      if (e.key === " ") { e.preventDefault(); $("play").click(); }
    });
    $("rpm").addEventListener("input", (e) => { S.rpm = +e.target.value; drawForce(); });
    $("compare-run").addEventListener("click", runCompare);
    let timer = null;
    $("editor").addEventListener("input", () => {
      if (REPORT) return;
      clearTimeout(timer);
      timer = setTimeout(() => requestAnalysis({ toml: $("editor").value, step_deg: S.result ? S.result.step_deg : 0.5 }), 120);
    });
    $("download-toml").addEventListener("click", () => save(new Blob([$("editor").value], { type: "application/toml" }), S.name || "mechanism.toml"));
    $("download-csv").addEventListener("click", () => download("api/csv", "analysis.csv"));
    $("download-report").addEventListener("click", () => download("api/report", "report.html"));
    window.addEventListener("resize", redraw);
  }

  function tick() {
    if (!S.playing || !S.result) return;
    setIndex((S.index + 1) % S.result.frames.length);
    requestAnimationFrame(tick);
  }

  function save(blob, name) {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.appendChild(a);
    a.click();
    setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  }

  function download(path, name) {
    post(path, { toml: $("editor").value, step_deg: S.result ? S.result.step_deg : 0.5 })
      .then((r) => r.blob())
      .then((b) => save(b, name))
      .catch(showError);
  }

  // ---------- start ----------
  function start() {
    setupControls();
    setupDrawing();
    if (REPORT) {
      document.body.classList.add("report");
      $("editor").readOnly = true;
      $("editor").value = REPORT.toml;
      S.name = REPORT.result.name;
      S.compare = REPORT.compare;
      show(REPORT.result, REPORT.toml, false);
      // a design review document: its title, its date, the profile's extent for the shop
      const rv = REPORT.review || {};
      document.title = `Design review — ${REPORT.result.name}`;
      $("title").textContent = `design review — ${REPORT.result.name}`;
      const u = REPORT.result.length_unit, sh = rv.shop;
      let extent = rv.radius ? ` Profile radius from ${fmt(rv.radius[0], 5)} to ${fmt(rv.radius[1], 5)} ${u}.` : "";
      if (sh) {
        const polar = sh.polar_radius.Ok
          ? `polar table (1°) radius ${fmt(sh.polar_radius.Ok[0], 6)} to ${fmt(sh.polar_radius.Ok[1], 6)} ${u}`
          : `no polar table (${sh.polar_radius.Err})`;
        const pitch = sh.pitch_radius ? `, pitch curve ${fmt(sh.pitch_radius[0], 6)} to ${fmt(sh.pitch_radius[1], 6)} ${u}` : "";
        extent = ` Shop (camkin profile): ${polar}${pitch}; DXF of ${sh.dxf_arcs} arcs within ${fmt(sh.dxf_deviation, 2)} ${u} of the exact curves.`;
      }
      const failed = (REPORT.result.checks || []).filter((c) => !c.ok).length;
      const verdict = REPORT.result.system ? "" : failed ? ` ${failed} design check${failed === 1 ? "" : "s"} failed (marked below).` : " Every design check passed.";
      setStatus(`Made ${rv.date || ""} by ${REPORT.generated_by} from ${REPORT.result.name}, whose text is below: everything is in this file.${verdict}${extent}`, failed > 0);
      $("footer").textContent = `Exact kinematics by the contact method (K. Lee, 2005). ${REPORT.generated_by}.`;
      if (!REPORT.compare) $("compare-panel").hidden = true;
      $("compare-n").disabled = true;
      return;
    }
    const session = BRIDGE
      ? Promise.resolve({ name: BRIDGE.name, toml: BRIDGE.toml })
      : fetch("api/session").then((r) => r.json());
    if (BRIDGE) document.body.classList.add("widget");
    session
      .then((s) => {
        S.name = s.name;
        S.toml = s.toml;
        $("editor").value = s.toml;
        requestAnalysis({ toml: s.toml });
        // the paper's study at N = 36 once the first result is in
        const wait = setInterval(() => { if (S.result) { clearInterval(wait); runCompare(); } }, 50);
      })
      .catch((e) => setStatus(`cannot reach the server: ${e}`, true));
    $("footer").textContent = BRIDGE
      ? "Exact kinematics by the contact method (K. Lee, 2005), computed in this notebook's kernel; the widget's mechanism attribute holds the edited mechanism."
      : "Exact kinematics by the contact method (K. Lee, 2005). The server runs on this machine only; closing the page loses unsaved edits: download the mechanism file.";
  }

  start();
})();
