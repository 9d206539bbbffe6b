/* springscene's player: a VPython run, recorded by springscene (docs/recording.md), replayed
   with GlowScript's own library in this page. The page's data (springscene's
   vpython/page/replay_data.py) holds one timeline per (object, attribute); showing a frame
   is a binary search in each, so any frame shows at once, backwards too. Canvases and
   objects are made as VPython's own client (glowcomm.js) makes them; each frame sets what
   changed. The camera is the program's at each frame until the user turns, zooms or pans
   a canvas with GlowScript's mouse controls; then the user's stays until "Follow the
   program's camera". Playing keeps to program time: frames are skipped, never slowed.
   window.springscene is the player, for the page's tests. */
(function () {
  "use strict";
  var started = performance.now();
  var data = JSON.parse(document.getElementById("springscene-recording").textContent);
  var page = document.getElementById("vp-page");
  window.__GSlang = "vpython";
  window.__context = { glowscript_container: $(page) };

  // The numbers (replay_data.py): base64 of zlib, bytes shuffled; timelines XORed by row
  function inflate(b64) {
    var s = atob(b64), bytes = new Uint8Array(s.length);
    for (var i = 0; i < s.length; i++) bytes[i] = s.charCodeAt(i);
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
    return new Response(stream).arrayBuffer().then(function (buf) {
      var b = new Uint8Array(buf), n = b.length / 4, out = new Uint8Array(b.length);
      for (var k = 0; k < 4; k++) for (var j = 0; j < n; j++) out[4 * j + k] = b[k * n + j];
      return out.buffer;
    });
  }
  function unxor(U) {
    data.objects.forEach(function (o) {
      for (var name in o.n) {
        var tl = o.n[name], d = tl[0], at = tl[1], end = d * tl[2];
        for (var i = d; i < end; i++) U[at + i] ^= U[at + i - d];
      }
    });
  }
  var F, I;
  var times = data.times, nframes = times.length;

  // the last i in [0, n) with at(i) <= k, or -1
  function search(at, n, k) {
    var lo = 0, hi = n - 1, found = -1;
    while (lo <= hi) {
      var mid = (lo + hi) >> 1;
      if (at(mid) <= k) { found = mid; lo = mid + 1; } else hi = mid - 1;
    }
    return found;
  }

  // A numeric timeline [dim, float offset, count, dense, first frame | int offset]
  function numIndex(tl, k) {
    if (tl[3]) return Math.min(k - tl[4], tl[2] - 1);
    return search(function (i) { return I[tl[4] + i]; }, tl[2], k);
  }
  function numValue(tl, i) {
    var at = tl[1] + tl[0] * i;
    return tl[0] === 3 ? vec(F[at], F[at + 1], F[at + 2]) : F[at];
  }
  // A JSON timeline [[frame, value], ...]
  function jsonIndex(tl, k) { return search(function (i) { return tl[i][0]; }, tl.length, k); }

  function glowValue(v) {
    if (Array.isArray(v) && v.length === 3 && typeof v[0] === "number") return vec(v[0], v[1], v[2]);
    return v;
  }

  // ---- canvases ------------------------------------------------------------------
  var CAMERA = ["center", "forward", "up", "range", "fov"];
  var canvases = {}, canvasList = [];

  function canvasValue(c, name, k) {
    var tl = c.t[name];
    if (!tl) return undefined;
    var i = jsonIndex(tl, k);
    return i < 0 ? tl[0][1] : tl[i][1];
  }

  function makeCanvas(c) {
    var box = document.createElement("div");
    box.className = "vp-canvas-box";
    page.appendChild(box);
    canvas.container = box;
    var cfg = { autoscale: false };
    ["width", "height", "userzoom", "userspin", "userpan"].forEach(function (name) {
      var v = canvasValue(c, name, 0);
      if (v !== undefined && v !== null) cfg[name] = v;
    });
    if (!canvasList.length) {                // the first canvas holds the widgets
      if (!c.t.title) c.t.title = [[0, ""]];
      if (!c.t.caption) c.t.caption = [[0, ""]];
    }
    var cvs = canvas(cfg);
    cvs.title_anchor;                       // activates it in its own box, title first
    var entry = { rec: c, glow: cvs, applied: {}, user: false, set: null };
    canvases[c.id] = entry;
    canvasList.push(entry);
  }

  function setLights(cvs, lights) {
    cvs.lights = [];
    (lights || []).forEach(function (L) {
      var color = glowValue(L.color || [1, 1, 1]);
      if (L.kind === "local_light") local_light({ canvas: cvs, pos: glowValue(L.pos), color: color });
      else distant_light({ canvas: cvs, direction: glowValue(L.direction), color: color });
    });
  }

  function showCanvas(entry, k) {
    var cvs = entry.glow, t = entry.rec.t;
    for (var name in t) {
      if (CAMERA.indexOf(name) >= 0) continue;
      var i = Math.max(jsonIndex(t[name], k), 0);
      if (entry.applied[name] === i) continue;
      entry.applied[name] = i;
      var v = t[name][i][1];
      if (name === "title" || name === "caption") {
        cvs[name] = entry === canvasList[0] ? withWidgets(v || "", data.widgets[name]) : v || "";
      }
      else if (name === "lights") setLights(cvs, v);
      else if (name === "background" || name === "ambient" || name === "foreground") {
        if (v) cvs[name] = glowValue(v);
      } else if (name === "width" || name === "height") { if (v) cvs[name] = v; }
      else if (name === "visible") cvs.wrapper.css("display", v === false ? "none" : "inline-block");
    }
    if (!entry.user) followCamera(entry, k);
  }

  // the page's widgets (disabled HTML) at their placeholders in the area, else after it
  function withWidgets(html, list) {
    var rest = "";
    (list || []).forEach(function (w) {
      var mark = "\u003c!--vpython-widget-" + w[0] + "--\u003e";
      if (w[0] !== null && html.indexOf(mark) >= 0) html = html.replace(mark, function () { return w[1]; });   // no $& patterns
      else rest += w[1];
    });
    return html + rest;
  }

  function vcopy(v) { return vec(v.x, v.y, v.z); }
  function vsame(a, b) { return Math.abs(a.x - b.x) + Math.abs(a.y - b.y) + Math.abs(a.z - b.z) < 1e-9 * (1 + a.mag); }

  // the program's camera at frame k, set with GlowScript's autoscale off
  function followCamera(entry, k) {
    var cvs = entry.glow;
    var center = canvasValue(entry.rec, "center", k), forward = canvasValue(entry.rec, "forward", k);
    var up = canvasValue(entry.rec, "up", k), range = canvasValue(entry.rec, "range", k);
    var fov = canvasValue(entry.rec, "fov", k);
    if (fov) cvs.fov = fov;
    if (center) cvs.center = glowValue(center);
    if (forward) cvs.forward = glowValue(forward);
    if (up) cvs.up = glowValue(up);
    if (range) cvs.range = range;
    cvs.autoscale = false;
    entry.set = { center: vcopy(cvs.__center), axis: vcopy(cvs.__axis), up: vcopy(cvs.__up),
                  range: cvs.__range };
  }

  // whether the user moved the camera (GlowScript's mouse) since the player set it
  function userMoved(entry) {
    var s = entry.set, cvs = entry.glow;
    if (!s) return false;
    return !(vsame(s.center, cvs.__center) && vsame(s.axis, cvs.__axis) && vsame(s.up, cvs.__up)
             && Math.abs(s.range - cvs.__range) <= 1e-9 * Math.abs(s.range));
  }

  // ---- objects -------------------------------------------------------------------
  var MAKERS = { box: box, sphere: sphere, simple_sphere: simple_sphere, ellipsoid: sphere,
                 cylinder: cylinder, cone: cone, pyramid: pyramid, arrow: arrow, helix: helix,
                 ring: ring, curve: curve, points: points, label: label };
  var FIRST = ["pos", "origin", "axis", "up", "size"];   // GlowScript links axis, up and size
  var NOT_SET = { retain: 1, round: 1, texture: 1, visible: 1, points: 1, canvas: 1 };
  var objects = [], byId = {};

  function attrOrder(o) {
    var names = Object.keys(o.n).concat(Object.keys(o.j));
    return names.sort(function (a, b) {
      var ia = FIRST.indexOf(a), ib = FIRST.indexOf(b);
      return (ia < 0 ? 99 : ia) - (ib < 0 ? 99 : ib) || (a < b ? -1 : a > b ? 1 : 0);
    });
  }

  function skipped(o, name) {
    if (NOT_SET[name]) return true;
    if (o.kind === "points") return name === "origin";       // added to each point instead
    if (o.kind === "label") return name === "axis" || name === "up" || name === "size";
    return false;
  }

  function valueAt(o, name, k) {
    if (o.n[name]) return numValue(o.n[name], Math.max(numIndex(o.n[name], k), 0));
    var tl = o.j[name], i = Math.max(jsonIndex(tl, k), 0);
    return glowValue(tl[i][1]);
  }

  function makeObject(o) {
    var cvs = canvases[o.canvas] ? canvases[o.canvas].glow : canvasList[0].glow;
    var cfg = { canvas: cvs, visible: false }, order = attrOrder(o);
    order.forEach(function (name) {
      if (skipped(o, name)) return;
      var v = valueAt(o, name, o.born);
      if (v === null && (o.kind !== "label")) return;
      cfg[name] = v;
    });
    if (o.kind === "arrow" && o.j.round) cfg.round = !!o.j.round[0][1];
    if (o.kind === "points" && o.j.size_units) cfg.size_units = o.j.size_units[0][1];
    if (o.kind === "curve" || o.kind === "points") delete cfg.opacity;
    var tex = o.j.texture && o.j.texture[0][1];
    if (tex && data.textures[tex]) cfg.texture = data.textures[tex];
    var g = MAKERS[o.kind](cfg);
    var entry = { rec: o, glow: g, order: order.filter(function (n) { return !skipped(o, n); }),
                  applied: {}, shown: false, pts: null };
    objects.push(entry);
    byId[o.id] = entry;
  }

  function showObject(entry, k) {
    var o = entry.rec, g = entry.glow;
    var alive = k >= o.born && (o.died === null || k < o.died);
    var vis = alive && (!(o.j.visible || o.n.visible) || !!valueAt(o, "visible", k));
    if (!alive) { if (entry.shown) { g.visible = false; entry.shown = false; } return; }
    for (var a = 0; a < entry.order.length; a++) {
      var name = entry.order[a], i;
      if (o.n[name]) i = Math.max(numIndex(o.n[name], k), 0);
      else i = Math.max(jsonIndex(o.j[name], k), 0);
      if (entry.applied[name] === i) continue;
      entry.applied[name] = i;
      var v = valueAt(o, name, k);
      if (v === null && o.kind !== "label") continue;
      try { g[name] = v; } catch (e) { /* an attribute GlowScript refuses for this kind */ }
    }
    if (o.p) showPoints(entry, k);
    if (vis !== entry.shown) { g.visible = vis; entry.shown = vis; }
  }

  // curve and points: which segment, and which slice of it, at frame k
  function showPoints(entry, k) {
    var p = entry.rec.p, i = search(function (j) { return I[p[1] + 4 * j]; }, p[2], k);
    var seg = -1, a = 0, b = 0;
    if (i >= 0) { seg = I[p[1] + 4 * i + 1]; a = I[p[1] + 4 * i + 2]; b = I[p[1] + 4 * i + 3]; }
    var now = entry.pts || { seg: -1, a: 0, b: 0 }, g = entry.glow;
    if (now.seg === seg && now.a === a && now.b === b) return;
    if (now.seg === seg && a >= now.a && b >= now.b && a <= now.b) {
      if (a > now.a) g.splice(0, a - now.a);
      if (b > now.b) g.push(pointList(entry, p[0][seg], now.b, b));
    } else {
      g.clear();
      if (seg >= 0 && b > a) g.push(pointList(entry, p[0][seg], a, b));
    }
    entry.pts = { seg: seg, a: a, b: b };
  }

  function pointList(entry, offset, a, b) {
    var out = [], o = entry.rec, origin = null;
    if (o.kind === "points" && (o.n.origin || o.j.origin)) origin = valueAt(o, "origin", o.born);
    for (var i = a; i < b; i++) {
      var at = offset + 7 * i, pos = vec(F[at], F[at + 1], F[at + 2]);
      var pt = { pos: origin ? pos.add(origin) : pos };
      if (F[at + 3] >= 0) pt.color = vec(F[at + 3], F[at + 4], F[at + 5]);   // its own colour
      if (F[at + 6] > 0) pt.radius = F[at + 6];                               // its own radius
      out.push(pt);
    }
    return out;
  }

  // ---- graphs, printed text --------------------------------------------------------
  var graphs = [];
  function makeGraphs() {
    if (!data.graphs.length) return;
    var area = document.createElement("div");
    area.className = "vp-graphs";
    page.appendChild(area);
    data.graphs.forEach(function (gr) {
      var series = data.series.filter(function (s) { return s.graph === gr.id; });
      graphs.push(SpringscenePlot(area, gr, series, F, I));
    });
  }

  var printedBox = null, printedLen = -1;
  function makePrinted() {
    if (data.printed) {
      printedBox = document.createElement("pre");
      printedBox.className = "vp-print";
      page.appendChild(printedBox);
    }
    if (data.end && data.end.error) {
      var err = document.createElement("pre");
      err.className = "vp-error";
      err.textContent = data.end.error;          // text, never markup
      page.appendChild(err);
    }
  }
  function showPrinted(k) {
    if (!printedBox) return;
    var i = search(function (j) { return data.printed_at[j][0]; }, data.printed_at.length, k);
    var n = i < 0 ? 0 : data.printed_at[i][1];
    if (n !== printedLen) { printedBox.textContent = data.printed.slice(0, n); printedLen = n; }
  }

  // ---- the player ----------------------------------------------------------------
  var state = { frame: -1, playing: false, speed: 1, wall0: 0, prog0: 0, shown: 0 };
  var ui = {};

  function show(k) {
    k = Math.max(0, Math.min(nframes - 1, k | 0));
    var t0 = performance.now();
    for (var c = 0; c < canvasList.length; c++) showCanvas(canvasList[c], k);
    for (var i = 0; i < objects.length; i++) showObject(objects[i], k);
    for (var g = 0; g < graphs.length; g++) graphs[g].show(k);
    showPrinted(k);
    state.frame = k;
    ui.slider.value = k;
    ui.time.textContent = "t = " + timeText(times[k]) + " / " + timeText(times[nframes - 1]);
    api.last_show_ms = performance.now() - t0;
    return api.last_show_ms;
  }

  // program seconds a second of playing (1; a config's atoms: its video's speed, 1e-12)
  var timeScale = (data.header && data.header.time_scale) || 1;
  var PREFIXES = [[1, ""], [1e-3, "m"], [1e-6, "\u00b5"], [1e-9, "n"], [1e-12, "p"], [1e-15, "f"]];
  function timeText(t) {        // seconds, with the prefix the run's length needs
    var end = Math.abs(times[nframes - 1]) || 1, p = PREFIXES[0];
    for (var i = 0; i < PREFIXES.length && end < 10 * PREFIXES[i][0]; i++) p = PREFIXES[i];
    if (end >= 10) p = PREFIXES[0];
    return (t / p[0]).toFixed(2) + " " + p[1] + "s";
  }

  function frameAt(t) { return Math.max(search(function (i) { return times[i]; }, nframes, t + 1e-9), 0); }

  function checkUser() {
    var any = false;
    canvasList.forEach(function (e) {
      if (!e.user && userMoved(e)) e.user = true;
      any = any || e.user;
    });
    ui.follow.disabled = !any;
  }

  function tick() {
    if (!state.playing) return;
    checkUser();
    var now = performance.now(), tEnd = times[nframes - 1];
    var t = state.prog0 + (now - state.wall0) / 1000 * state.speed * timeScale;
    var k = frameAt(Math.min(t, tEnd));
    if (k !== state.frame) { show(k); state.shown++; }
    if (t >= tEnd) {
      api.playback = { program_s: tEnd - state.prog0, wall_s: (now - state.wall0) / 1000,
                       speed: state.speed, frames_shown: state.shown, frames: nframes };
      pause();
      return;
    }
    if (document.hidden) setTimeout(tick, 20); else requestAnimationFrame(tick);
  }

  function play() {
    if (state.frame >= nframes - 1) show(0);
    state.playing = true;
    state.wall0 = performance.now();
    state.prog0 = times[state.frame];
    state.shown = 0;
    api.playback = null;
    ui.play.textContent = "\u275A\u275A";
    ui.play.title = "pause";
    requestAnimationFrame(tick);
  }
  function pause() {
    state.playing = false;
    ui.play.textContent = "\u25B6";
    ui.play.title = "play";
  }
  function seek(k) {
    checkUser();
    var ms = show(k);
    if (state.playing) { state.wall0 = performance.now(); state.prog0 = times[state.frame]; }
    return ms;
  }
  function follow() {
    canvasList.forEach(function (e) { e.user = false; followCamera(e, state.frame); });
    ui.follow.disabled = true;
  }

  function makeBar() {
    var bar = document.getElementById("vp-player");
    function el(tag, props) { var x = document.createElement(tag); for (var p in props) x[p] = props[p]; bar.appendChild(x); return x; }
    ui.play = el("button", { type: "button", className: "vp-play" });
    ui.slider = el("input", { type: "range", min: 0, max: nframes - 1, step: 1, value: 0, className: "vp-seek", title: "frame" });
    ui.time = el("span", { className: "vp-time" });
    var label = el("label", { className: "vp-speed-label", textContent: "speed " });
    ui.speed = document.createElement("select");
    ui.speed.className = "vp-speed";
    [0.25, 0.5, 1, 2, 4].forEach(function (s) {
      var opt = document.createElement("option");
      opt.value = s; opt.textContent = s + "\u00D7"; opt.selected = s === 1;
      ui.speed.appendChild(opt);
    });
    label.appendChild(ui.speed);
    ui.follow = el("button", { type: "button", className: "vp-follow", disabled: true,
                               textContent: "Follow the program's camera",
                               title: "you turned, zoomed or panned a canvas; go back to the program's camera" });
    ui.play.onclick = function () { if (state.playing) pause(); else play(); };
    ui.slider.oninput = function () { seek(+ui.slider.value); };
    ui.speed.onchange = function () {
      state.speed = +ui.speed.value;
      if (state.playing) { state.wall0 = performance.now(); state.prog0 = times[state.frame]; }
    };
    ui.follow.onclick = follow;
    pause();
  }

  var api = {
    ready: false, frames: nframes, times: times, playback: null, last_show_ms: 0,
    play: play, pause: pause, seek: seek, follow: follow,
    frame: function () { return state.frame; },
    playing: function () { return state.playing; },
    object: function (id) { return byId[id] ? byId[id].glow : null; },
    canvas: function (id) { return canvases[id] ? canvases[id].glow : null; },
    user_camera: function (id) { checkUser(); return canvases[id] ? canvases[id].user : null; },
    left_out: data.left_out
  };
  window.springscene = api;

  makeBar();
  if (!nframes) { ui.time.textContent = "the recording has no frame"; return; }
  Promise.all([inflate(data.f32), inflate(data.i32)]).then(function (buffers) {
    unxor(new Uint32Array(buffers[0]));
    F = new Float32Array(buffers[0]);
    I = new Int32Array(buffers[1]);
    start();
  }, function (e) { ui.time.textContent = "this browser cannot read the recording: " + e; });

  function start() {
    data.canvases.forEach(makeCanvas);
    if (!canvasList.length) makeCanvas({ id: 0, t: {} });
    data.objects.forEach(function (o) { if (MAKERS[o.kind]) makeObject(o); });
    makeGraphs();
    makePrinted();
    var left = Object.keys(data.left_out);
    if (left.length) {
      var note = document.getElementById("vp-left-out");
      note.textContent = "Not drawn in this page: " + left.map(function (k) {
        return data.left_out[k] + " " + k; }).join(", ") +
        " (springscene's video and still of the run draw them).";
    }
    show(data.at_end ? nframes - 1 : 0);       // a still's page opens at its picture
    api.ready = true;
    api.setup_ms = performance.now() - started;
    // playing starts when GlowScript has drawn the first frame (its meshes made), as VPython's
    // program starts when its page is up
    var first = canvasList[0].glow;
    function firstDrawn() {
      first.unbind("draw_complete", firstDrawn);
      api.first_drawn_ms = performance.now() - started;
      if (!/[#&]paused\b/.test(location.hash) && !state.playing && state.frame === 0) play();
    }
    first.bind("draw_complete", firstDrawn);
  }
})();
