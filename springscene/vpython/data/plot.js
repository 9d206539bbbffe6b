/* springscene's graphs for the interactive page: one VPython graph drawn on a 2D canvas,
   its series' points up to the frame shown (GlowScript draws graphs with Plotly, 3.8 MB;
   this draws gcurve, gdots, gvbars and ghbars as VPython's graph shows them). Titles are
   text, never markup. SpringscenePlot(area, graph, series, F, I) appends the graph to
   area and returns {show(k)}. */
function SpringscenePlot(area, gr, series, F, I) {
  "use strict";
  var W = gr.width || 640, H = gr.height || 400;
  var box = document.createElement("div");
  box.className = "vp-graph";
  var cv = document.createElement("canvas");
  cv.width = W; cv.height = H;
  box.appendChild(cv);
  area.appendChild(box);
  var ctx = cv.getContext("2d");
  var M = { left: 70, right: 20, top: gr.title ? 34 : 14, bottom: gr.xtitle ? 50 : 32 };
  var shownKey = null;

  function css(c, fallback) {
    if (!c) return fallback;
    return "rgb(" + c.map(function (v) { return Math.round(255 * Math.min(1, Math.max(0, v))); }).join(",") + ")";
  }
  function stateAt(s, k) {     // [offset of the segment's floats, first point, end point]
    var p = s.p, lo = 0, hi = p[2] - 1, i = -1;
    while (lo <= hi) { var m = (lo + hi) >> 1; if (I[p[1] + 4 * m] <= k) { i = m; lo = m + 1; } else hi = m - 1; }
    if (i < 0) return null;
    return [p[0][I[p[1] + 4 * i + 1]], I[p[1] + 4 * i + 2], I[p[1] + 4 * i + 3]];
  }
  function niceStep(span) {
    var raw = span / 6, mag = Math.pow(10, Math.floor(Math.log10(raw))), r = raw / mag;
    return mag * (r < 1.5 ? 1 : r < 3 ? 2 : r < 7 ? 5 : 10);
  }
  function bounds(states) {
    var b = { x0: Infinity, x1: -Infinity, y0: Infinity, y1: -Infinity };
    states.forEach(function (st, j) {
      if (!st) return;
      var bars = series[j].kind === "gvbars" || series[j].kind === "ghbars";
      for (var i = st[1]; i < st[2]; i++) {
        var x = F[st[0] + 2 * i], y = F[st[0] + 2 * i + 1];
        b.x0 = Math.min(b.x0, x); b.x1 = Math.max(b.x1, x);
        b.y0 = Math.min(b.y0, y); b.y1 = Math.max(b.y1, y);
      }
      if (bars) { b.y0 = Math.min(b.y0, 0); b.x0 = Math.min(b.x0, 0); }
    });
    if (gr.xmin !== null && gr.xmin !== undefined) b.x0 = gr.xmin;
    if (gr.xmax !== null && gr.xmax !== undefined) b.x1 = gr.xmax;
    if (gr.ymin !== null && gr.ymin !== undefined) b.y0 = gr.ymin;
    if (gr.ymax !== null && gr.ymax !== undefined) b.y1 = gr.ymax;
    if (!isFinite(b.x0)) { b.x0 = 0; b.x1 = 1; }
    if (!isFinite(b.y0)) { b.y0 = 0; b.y1 = 1; }
    if (b.x1 <= b.x0) { b.x0 -= 0.5; b.x1 += 0.5; }
    if (b.y1 <= b.y0) { b.y0 -= 0.5; b.y1 += 0.5; }
    var pad = 0.05 * (b.y1 - b.y0);               // as Plotly's autorange, data off the frame
    if (gr.ymin === null || gr.ymin === undefined) b.y0 -= pad;
    if (gr.ymax === null || gr.ymax === undefined) b.y1 += pad;
    return b;
  }
  function tick(v, step) { return (Math.abs(v) < 1e-9 * step ? 0 : +v.toPrecision(6)) + ""; }
  function legend() {
    var named = series.filter(function (s) { return s.label && s.visible !== false; });
    if (!named.length) return;
    ctx.font = "12px Verdana, Arial, sans-serif";
    var w = 0;
    named.forEach(function (s) { w = Math.max(w, ctx.measureText(s.label).width); });
    var x = W - M.right - w - 40, y = M.top + 6;
    ctx.fillStyle = "rgba(255,255,255,0.85)"; ctx.strokeStyle = "#ccc";
    ctx.fillRect(x, y, w + 34, 18 * named.length + 6); ctx.strokeRect(x, y, w + 34, 18 * named.length + 6);
    ctx.textAlign = "left"; ctx.textBaseline = "middle";
    named.forEach(function (s, i) {
      var cy = y + 12 + 18 * i, color = css(s.color, "#000");
      ctx.fillStyle = ctx.strokeStyle = color; ctx.lineWidth = 2;
      if (s.kind === "gdots") { ctx.beginPath(); ctx.arc(x + 14, cy, 3, 0, 2 * Math.PI); ctx.fill(); }
      else { ctx.beginPath(); ctx.moveTo(x + 5, cy); ctx.lineTo(x + 23, cy); ctx.stroke(); }
      ctx.fillText(s.label, x + 28, cy);
    });
  }
  function axes(b, X, Y) {
    var fg = css(gr.foreground, "#000");
    ctx.fillStyle = css(gr.background, "#fff");
    ctx.fillRect(0, 0, W, H);
    ctx.strokeStyle = "#ddd"; ctx.fillStyle = fg; ctx.lineWidth = 1;
    ctx.font = "12px Verdana, Arial, sans-serif";
    var sx = niceStep(b.x1 - b.x0), sy = niceStep(b.y1 - b.y0);
    ctx.textAlign = "center"; ctx.textBaseline = "top";
    for (var x = Math.ceil(b.x0 / sx) * sx; x <= b.x1 + 1e-9 * sx; x += sx) {
      ctx.beginPath(); ctx.moveTo(X(x), M.top); ctx.lineTo(X(x), H - M.bottom); ctx.stroke();
      ctx.fillText(tick(x, sx), X(x), H - M.bottom + 4);
    }
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    for (var y = Math.ceil(b.y0 / sy) * sy; y <= b.y1 + 1e-9 * sy; y += sy) {
      ctx.beginPath(); ctx.moveTo(M.left, Y(y)); ctx.lineTo(W - M.right, Y(y)); ctx.stroke();
      ctx.fillText(tick(y, sy), M.left - 4, Y(y));
    }
    ctx.strokeStyle = fg;
    ctx.strokeRect(M.left, M.top, W - M.left - M.right, H - M.top - M.bottom);
    ctx.textAlign = "center"; ctx.textBaseline = "alphabetic";
    if (gr.title) { ctx.font = "15px Verdana, Arial, sans-serif"; ctx.fillText(gr.title, W / 2, 22); }
    ctx.font = "13px Verdana, Arial, sans-serif";
    if (gr.xtitle) ctx.fillText(gr.xtitle, (M.left + W - M.right) / 2, H - 10);
    if (gr.ytitle) {
      ctx.save(); ctx.translate(16, (M.top + H - M.bottom) / 2); ctx.rotate(-Math.PI / 2);
      ctx.fillText(gr.ytitle, 0, 0); ctx.restore();
    }
  }
  function drawSeries(s, st, X, Y) {
    if (!st || s.visible === false) return;
    var color = css(s.color, "#000"), r = s.radius || 3;
    ctx.strokeStyle = ctx.fillStyle = color;
    ctx.lineWidth = s.width || 2;
    ctx.save();
    ctx.beginPath(); ctx.rect(M.left, M.top, W - M.left - M.right, H - M.top - M.bottom); ctx.clip();
    var delta = s.delta || 1;
    if (s.kind === "gcurve") ctx.beginPath();
    for (var i = st[1]; i < st[2]; i++) {
      var x = F[st[0] + 2 * i], y = F[st[0] + 2 * i + 1];
      if (s.kind === "gcurve") { if (i === st[1]) ctx.moveTo(X(x), Y(y)); else ctx.lineTo(X(x), Y(y)); }
      else if (s.kind === "gdots") { ctx.beginPath(); ctx.arc(X(x), Y(y), r, 0, 2 * Math.PI); ctx.fill(); }
      else if (s.kind === "gvbars") ctx.fillRect(X(x - delta / 2), Y(Math.max(y, 0)), X(x + delta / 2) - X(x - delta / 2), Math.abs(Y(y) - Y(0)));
      else if (s.kind === "ghbars") ctx.fillRect(X(Math.min(y, 0)), Y(x + delta / 2), Math.abs(X(y) - X(0)), Y(x - delta / 2) - Y(x + delta / 2));
    }
    if (s.kind === "gcurve") ctx.stroke();
    if (s.kind === "gcurve" && s.dot && st[2] > st[1]) {
      var last = st[0] + 2 * (st[2] - 1);
      ctx.beginPath(); ctx.arc(X(F[last]), Y(F[last + 1]), s.dot_radius || 3, 0, 2 * Math.PI); ctx.fill();
    }
    ctx.restore();
  }
  function show(k) {
    var states = series.map(function (s) { return stateAt(s, k); });
    var key = JSON.stringify(states);
    if (key === shownKey) return;
    shownKey = key;
    var b = bounds(states);
    var X = function (x) { return M.left + (x - b.x0) / (b.x1 - b.x0) * (W - M.left - M.right); };
    var Y = function (y) { return H - M.bottom - (y - b.y0) / (b.y1 - b.y0) * (H - M.top - M.bottom); };
    axes(b, X, Y);
    series.forEach(function (s, j) { drawSeries(s, states[j], X, Y); });
    legend();
  }
  return { show: show, element: cv };
}
