// camkin studio's line charts: a series over the cam angle (or another axis), its ticks, the
// failed checks marked at their angles and the cursor; numbers formatted for people. Loaded
// before studio.js (the server serves them as one script), no state of its own.
"use strict";
window.CamkinChart = (function () {
  function fmt(x, digits) {
    if (x === null || x === undefined || !isFinite(x)) return "—";
    const a = Math.abs(x);
    if (a !== 0 && (a >= 1e6 || a < 1e-3)) return x.toExponential((digits || 4) - 1);
    return Number(x.toPrecision(digits || 5)).toString();
  }

  function fitCanvas(c) {
    const dpr = window.devicePixelRatio || 1;
    const w = c.clientWidth || c.width, h = c.clientHeight || c.height;
    if (c.width !== Math.round(w * dpr) || c.height !== Math.round(h * dpr)) {
      c.width = Math.round(w * dpr);
      c.height = Math.round(h * dpr);
    }
    const g = c.getContext("2d");
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    return { g, w, h };
  }

  function niceTicks(lo, hi, n) {
    const span = hi - lo;
    if (!(span > 0)) return [lo];
    const raw = span / n, mag = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) || 10 * mag;
    const out = [];
    for (let t = Math.ceil(lo / step) * step; t <= hi + 1e-9 * span; t += step) out.push(Math.abs(t) < 1e-12 * span ? 0 : t);
    return out;
  }

  function quantile(sorted, q) { return sorted[Math.min(sorted.length - 1, Math.max(0, Math.floor(q * (sorted.length - 1))))]; }

  function yRange(p) {
    const vals = [];
    for (const s of p.series) for (const v of s.values) if (v !== null && isFinite(v) && (!p.log || v > 0)) vals.push(p.log ? Math.log10(v) : v);
    if (!vals.length) return [0, 1];
    vals.sort((a, b) => a - b);
    let lo = vals[0], hi = vals[vals.length - 1];
    if (p.clip && vals.length > 20) {
      // a radius of curvature near a straight stretch, or jerk at nodes, would flatten the rest
      const q1 = quantile(vals, 0.02), q3 = quantile(vals, 0.98), w = q3 - q1;
      lo = Math.max(lo, q1 - 0.5 * w); hi = Math.min(hi, q3 + 0.5 * w);
    }
    // a quantity that is zero but for rounding (the pressure angle under a flat face) is drawn
    // on a span that shows it as zero, not its rounding noise
    const minSpan = p.minSpan || 0;
    if (hi - lo < minSpan) { const m = (hi + lo) / 2; lo = m - minSpan / 2; hi = m + minSpan / 2; }
    if (lo === hi) { lo -= 1; hi += 1; }
    const pad = 0.06 * (hi - lo);
    return [lo - pad, hi + pad];
  }

  // p: {canvas, series, title, unit, x?, xr?, xunit?, log?, clip?, minSpan?, shade?, legend?,
  // noMarks?, cursor?}; result: the analysis (its angles, checks and step); cursorAngle: where
  // the red cursor stands unless p.cursor says otherwise
  function draw(p, result, cursorAngle) {
    const { g, w, h } = fitCanvas(p.canvas);
    const L = 64, R = 10, T = 16, B = 18;
    const x = p.x || result.angles_deg;
    // the x axis: the cam angle over a revolution, or p.xr = [lo, hi] in p.xunit
    const [x0, x1] = p.xr || [0, 360];
    const [ylo, yhi] = yRange(p);
    const X = (a) => L + ((a - x0) / (x1 - x0)) * (w - L - R);
    const Y = (v) => T + (1 - (v - ylo) / (yhi - ylo)) * (h - T - B);
    p.geom = { L, R, T, B, w, h, X, Y, ylo, yhi, x };
    g.clearRect(0, 0, w, h);
    g.fillStyle = "#fff"; g.fillRect(0, 0, w, h);
    g.font = "11px DejaVu Sans, sans-serif";
    // grid and axes
    g.strokeStyle = "#eee"; g.lineWidth = 1; g.fillStyle = "#555";
    for (const t of niceTicks(ylo, yhi, 4)) {
      const yy = Y(t);
      g.beginPath(); g.moveTo(L, yy); g.lineTo(w - R, yy); g.stroke();
      g.textAlign = "right";
      g.fillText(p.log ? `1e${Math.round(t)}` : fmt(t, 3), L - 4, yy + 4);
    }
    const xticks = p.xr ? niceTicks(x0, x1, 6).filter((t) => t >= x0 && t <= x1) : [0, 45, 90, 135, 180, 225, 270, 315, 360];
    for (const a of xticks) {
      const xx = X(a);
      g.beginPath(); g.moveTo(xx, T); g.lineTo(xx, h - B); g.stroke();
      g.textAlign = "center";
      g.fillText(p.xr ? `${fmt(a, 4)} ${p.xunit}` : `${a}°`, xx, h - 5);
    }
    if (!p.log && ylo < 0 && yhi > 0) {
      g.strokeStyle = "#bbb"; g.beginPath(); g.moveTo(L, Y(0)); g.lineTo(w - R, Y(0)); g.stroke();
    }
    g.textAlign = "left"; g.fillStyle = "#222"; g.font = "12px DejaVu Sans, sans-serif";
    g.fillText(p.unit ? `${p.title} (${p.unit})` : p.title, L + 4, 12);
    // failed checks at their angles
    if (result && !p.noMarks) {
      // a light band over the plot and a solid strip under it, so the curve stays readable
      const cell = Math.max(2, X(result.step_deg) - X(0));
      for (const ch of result.checks) {
        if (ch.ok) continue;
        for (const a of ch.angles_deg) {
          g.fillStyle = "rgba(214,39,40,0.08)";
          g.fillRect(X(a) - cell / 2, T, cell, h - T - B);
          g.fillStyle = "rgba(214,39,40,0.9)";
          g.fillRect(X(a) - cell / 2, h - B - 4, cell, 4);
        }
      }
    }
    if (p.shade) p.shade(g, X, Y, T, h - B);
    // the curves
    g.save();
    g.beginPath(); g.rect(L, T, w - L - R, h - T - B); g.clip();
    for (const s of p.series) {
      g.strokeStyle = s.color; g.lineWidth = s.width || 1.5;
      if (s.dash) g.setLineDash(s.dash);
      g.beginPath();
      let on = false;
      s.values.forEach((v, i) => {
        const ok = v !== null && isFinite(v) && (!p.log || v > 0);
        if (!ok) { on = false; return; }
        const xx = X(x[i]), yy = Y(p.log ? Math.log10(v) : v);
        if (on) g.lineTo(xx, yy); else g.moveTo(xx, yy);
        on = true;
      });
      g.stroke();
      g.setLineDash([]);
    }
    g.restore();
    // the cursor at the current angle (or where p.cursor puts it; none where it says null)
    const xcv = p.cursor ? p.cursor() : cursorAngle;
    if (xcv !== null && xcv >= x0 && xcv <= x1) {
      const xc = X(xcv);
      g.strokeStyle = "#d62728"; g.lineWidth = 1;
      g.beginPath(); g.moveTo(xc, T); g.lineTo(xc, h - B); g.stroke();
    }
    if (p.legend) {
      let lx = w - R - 6;
      g.textAlign = "right"; g.font = "11px DejaVu Sans, sans-serif";
      for (const s of p.series.slice().reverse()) {
        g.fillStyle = s.color;
        g.fillText(s.label, lx, 12);
        lx -= g.measureText(s.label).width + 14;
      }
    }
  }

  return { fmt, fitCanvas, draw };
})();
