// camkin studio's drawing of a mechanism at one frame, the parts with no state of their own:
// the cam's frame, the follower's (or every body's) shapes from the server, the contact and
// its normal, the sense of rotation, the key. Loaded before studio.js (one script).
"use strict";
window.CamkinScene = (function () {
  function camToWorld(frame, p) {
    const [ox, oy, a] = frame.cam, c = Math.cos(a), s = Math.sin(a);
    return [ox + c * p[0] - s * p[1], oy + s * p[0] + c * p[1]];
  }
  function worldToCam(frame, p) {
    const [ox, oy, a] = frame.cam, c = Math.cos(a), s = Math.sin(a);
    const dx = p[0] - ox, dy = p[1] - oy;
    return [c * dx + s * dy, -s * dx + c * dy];
  }

  // the drawing's key, top right: what each colour and mark is
  function legendItems(r) {
    const items = r.system
      ? [["none", "", "each body in its colour"], ["dot", "#d62728", "contact points"], ["line", "#2ca02c", "common normals"]]
      : [["fill", "#1f77b4", "cam, the driver (turns)"], ["line", "#3c3c3c", "follower"],
        ["dot", "#d62728", "contact point"], ["dash", "#2ca02c", "common normal"]];
    if (!r.system && r.nodes_editable) items.push(["node", "#1f77b4", "spline node (drag)"]);
    return items;
  }

  function drawLegend(g, r, w) {
    const items = legendItems(r);
    g.font = "11px DejaVu Sans, sans-serif";
    const tw = Math.max(...items.map((it) => g.measureText(it[2]).width));
    const x = w - tw - 40, lh = 15;
    g.fillStyle = "rgba(255,255,255,0.85)";
    g.fillRect(x - 6, 6, tw + 40, items.length * lh + 8);
    items.forEach(([kind, col, label], i) => {
      const y = 16 + i * lh;
      g.strokeStyle = col; g.fillStyle = col; g.lineWidth = 2; g.setLineDash([]);
      if (kind === "fill") { g.fillStyle = "rgba(31,119,180,0.15)"; g.fillRect(x, y - 5, 20, 10); g.strokeRect(x, y - 5, 20, 10); }
      else if (kind === "line") { g.beginPath(); g.moveTo(x, y); g.lineTo(x + 20, y); g.stroke(); }
      else if (kind === "dash") { g.lineWidth = 1.2; g.setLineDash([4, 3]); g.beginPath(); g.moveTo(x, y); g.lineTo(x + 20, y); g.stroke(); g.setLineDash([]); }
      else if (kind === "dot") { g.beginPath(); g.arc(x + 10, y, 4, 0, 2 * Math.PI); g.fill(); }
      else if (kind === "node") { g.beginPath(); g.arc(x + 10, y, 3.5, 0, 2 * Math.PI); g.fill(); }
      g.fillStyle = "#333";
      g.fillText(label, x + 26, y + 4);
    });
  }

  // the cam: its profile turned with it, stretches the follower cannot follow, its axis, nodes
  function drawShapes(g, r, f, view, k) {
    for (const s of f.follower) {
      g.strokeStyle = s.color;
      g.fillStyle = s.color;
      g.lineWidth = s.width || 1;
      if (s.t === "line") {
        g.beginPath();
        s.pts.forEach((p, i) => { const q = view.tx(p); if (i === 0) g.moveTo(q[0], q[1]); else g.lineTo(q[0], q[1]); });
        if (s.closed) g.closePath();
        g.stroke();
      } else if (s.t === "circle") {
        const q = view.tx(s.c);
        g.beginPath(); g.arc(q[0], q[1], s.r * k, 0, 2 * Math.PI); g.stroke();
      } else if (s.t === "dot") {
        const q = view.tx(s.p);
        g.beginPath(); g.arc(q[0], q[1], s.px, 0, 2 * Math.PI); g.fill();
      } else if (s.t === "curve") {
        // a closed curve of the follower, kept once in its body frame, placed at this pose
        const [ox, oy, an] = s.pose, c = Math.cos(an), sn = Math.sin(an);
        g.beginPath();
        r.curves[s.i].forEach((p, i) => {
          const q = view.tx([ox + c * p[0] - sn * p[1], oy + sn * p[0] + c * p[1]]);
          if (i === 0) g.moveTo(q[0], q[1]); else g.lineTo(q[0], q[1]);
        });
        g.closePath();
        g.stroke();
      }
    }
  }

  // the contact point and the common normal, and marks where a check fails
  function drawContact(g, r, f, view, size) {
    // marks of failed checks at this angle's neighbourhood: contacts where a check fails
    for (const ch of r.checks) {
      if (ch.ok) continue;
      for (const a of ch.angles_deg) {
        const i = Math.round(a / r.step_deg) % r.frames.length;
        const ct = r.frames[i] && r.frames[i].contact;
        if (!ct) continue;
        const q = view.tx(camToWorld(f, worldToCam(r.frames[i], ct)));
        g.fillStyle = "rgba(214,39,40,0.6)";
        g.fillRect(q[0] - 2, q[1] - 2, 4, 4);
      }
    }
    // the contact point and the common normal
    if (f.contact) {
      const q = view.tx(f.contact);
      if (f.normal) {
        const L = 0.3 * size;
        const a = view.tx([f.contact[0] - L * f.normal[0], f.contact[1] - L * f.normal[1]]);
        const b = view.tx([f.contact[0] + L * f.normal[0], f.contact[1] + L * f.normal[1]]);
        g.strokeStyle = "#2ca02c"; g.lineWidth = 1; g.setLineDash([5, 4]);
        g.beginPath(); g.moveTo(a[0], a[1]); g.lineTo(b[0], b[1]); g.stroke();
        g.setLineDash([]);
      }
      g.fillStyle = "#d62728";
      g.beginPath(); g.arc(q[0], q[1], 5, 0, 2 * Math.PI); g.fill();
    }
  }

  // a readout within 1e-9 of its series' largest magnitude is rounding: shown as 0
  // the cam's sense of rotation: an arc round its axis with an arrowhead, from how its pose
  // turns from one frame to the next
  function drawSense(g, r, view, size) {
    if (r.system || r.frames.length <= 1) return;
    let d = r.frames[1].cam[2] - r.frames[0].cam[2];
    d = Math.atan2(Math.sin(d), Math.cos(d));
    if (d !== 0) {
      const sgn = Math.sign(d), rr = 0.12 * size;
      const pt = (t) => view.tx([r.pivot[0] + rr * Math.cos(t), r.pivot[1] + rr * Math.sin(t)]);
      const a0 = sgn * Math.PI / 6, a1 = sgn * (5 * Math.PI / 6);
      g.strokeStyle = "#1f77b4"; g.lineWidth = 1.2;
      g.beginPath();
      for (let i = 0; i <= 24; i++) {
        const q = pt(a0 + (a1 - a0) * i / 24);
        if (i) g.lineTo(q[0], q[1]); else g.moveTo(q[0], q[1]);
      }
      g.stroke();
      const tip = pt(a1), back = pt(a1 - sgn * 0.25);
      const ux = back[0] - tip[0], uy = back[1] - tip[1], n = Math.hypot(ux, uy) || 1;
      const hl = 8;
      for (const s2 of [-0.5, 0.5]) {
        const c2 = Math.cos(s2), s3 = Math.sin(s2);
        g.beginPath(); g.moveTo(tip[0], tip[1]);
        g.lineTo(tip[0] + hl * (c2 * ux - s3 * uy) / n, tip[1] + hl * (s3 * ux + c2 * uy) / n);
        g.stroke();
      }
    }
  }

  return { camToWorld, worldToCam, legendItems, drawLegend, drawShapes, drawContact, drawSense };
})();
