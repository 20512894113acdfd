// Player for the book's moving figures (figures/animate.py writes the data).
// Every pose is computed by `mech` when the book is built; this script draws them. A live
// figure (data.live) also loads book/_static/mech/live.js, which re-solves it on a change.
// It is inlined once per figure (the guard below defines it once per page), so a page
// works offline and as a plain notebook output. Comment lines are stripped when inlined.
(function () {
  if (window.mechFig) { window.mechFig.scan(); return; }
  var NS = "http://www.w3.org/2000/svg";
  function el(parent, tag, attrs) {
    var e = document.createElementNS(NS, tag);
    for (var k in attrs) e.setAttribute(k, attrs[k]);
    parent.appendChild(e);
    return e;
  }
  // A path through a list of [x, y] points; a null point breaks the line (no pose there).
  function pathD(pts, close) {
    var d = "", pen = false;
    for (var i = 0; i < pts.length; i++) {
      var p = pts[i];
      if (!p) { pen = false; continue; }
      d += (pen ? "L" : "M") + p[0].toFixed(1) + " " + p[1].toFixed(1);
      pen = true;
    }
    return close && d ? d + "Z" : d;
  }
  // Labels that never collide: each label tries a few places around its point (up right,
  // up left, down right, down left, above, below) and takes the first whose box overlaps
  // no label placed before it in this drawing (the first place when none is free).
  function overlaps(a, b) {
    // a text box is taller than its ink: the boxes may touch by 12 % of a height
    var h = 0.12 * Math.min(a.height, b.height);
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y + h < b.y + b.height - h && b.y + h < a.y + a.height - h;
  }
  function place(t, q, off, placed) {
    var spots = [[1, -1, "start"], [-1, -1, "end"], [1, 1.6, "start"], [-1, 1.6, "end"], [0, -1.5, "middle"],
                 [0, 2.2, "middle"], [1.6, 0.5, "start"], [-1.6, 0.5, "end"]], first = null;
    for (var k = 0; k < spots.length; k++) {
      t.setAttribute("x", q[0] + spots[k][0] * off);
      t.setAttribute("y", q[1] + spots[k][1] * off);
      t.setAttribute("text-anchor", spots[k][2]);
      var b = t.getBBox();
      if (!first) first = [k, b];
      if (!b.width || !placed.some(function (p) { return overlaps(p, b); })) { placed.push(b); return; }
    }
    var s0 = spots[first[0]];
    t.setAttribute("x", q[0] + s0[0] * off);
    t.setAttribute("y", q[1] + s0[1] * off);
    t.setAttribute("text-anchor", s0[2]);
    placed.push(first[1]);
  }
  // The point of frame f in a flat array with `dim` numbers per frame (null: no pose).
  function at(arr, f, dim) {
    // A fixed point is stored once, not once per frame.
    var i = arr.length === dim ? 0 : f * dim;
    return arr[i] === null ? null : arr.slice(i, i + dim);
  }

  // The play button and the slider: shared by planar and 3-D figures.
  function controls(div, data, draw) {
    var n = data.n, play = div.querySelector(".mech-play"),
        slider = div.querySelector(".mech-slider"), out = div.querySelector(".mech-value"),
        timer = null;
    function show(f) {
      f = ((f % n) + n) % n;
      div.setAttribute("data-frame", f);
      slider.value = f;
      if (out) out.textContent = data.label + " = " + data.inputs[f];
      draw(f);
    }
    function stop() { clearInterval(timer); timer = null; play.textContent = "\u25B6 play"; }
    play.addEventListener("click", function () {
      if (timer) { stop(); return; }
      play.textContent = "\u275A\u275A pause";
      // setInterval rather than requestAnimationFrame: it keeps a fixed pose rate and
      // still runs in a headless browser, where the browser test drives the page.
      timer = setInterval(function () { show(+div.getAttribute("data-frame") + 1); }, 1000 / data.fps);
    });
    slider.addEventListener("input", function () { stop(); show(+slider.value); });
    div.querySelectorAll(".mech-mark").forEach(function (b) {
      b.addEventListener("click", function () { stop(); show(+b.getAttribute("data-to")); });
    });
    show(+div.getAttribute("data-frame") || 0);
  }

  // Planar figure: the SVG's user units are the integer grid of the data (y already down).
  function planar(div, d) {
    var svg = div.querySelector("svg"), u = d.unit, layer = {};
    ["fix", "mark", "ghost", "path", "link", "top"].forEach(function (k) { layer[k] = el(svg, "g", {}); });
    function pts(P, f) { return d.names.map(function (_, i) { return at(P[i], f, 2); }); }
    function body(g, P, f, cls) {
      var p = pts(P, f);
      d.links.forEach(function (l) {
        var q = l.map(function (i) { return p[i]; });
        if (q.indexOf(null) < 0) el(g, "path", {d: pathD(q, q.length > 2), class: cls + (q.length > 2 ? " mf-plate" : "")});
      });
      return p;
    }
    // Still parts: the guides, the whole path of each traced point (faint) and the marked
    // poses; drawn again when a live figure changes its linkage (d.curves: a finer path).
    var trace = [];
    function stills() {
      ["fix", "path", "mark"].forEach(function (k) { layer[k].textContent = ""; });
      d.lines.forEach(function (l) { el(layer.fix, "path", {d: pathD(l), class: "mf-guide"}); });
      d.trace.forEach(function (i, k) {
        var all = d.curves && d.curves[k];
        if (!all) { all = []; for (var f = 0; f < d.n; f++) all.push(at(d.P[i], f, 2)); }
        el(layer.path, "path", {d: pathD(all), class: "mf-path-all"});
      });
      d.marks.forEach(mark);
      trace = d.trace.map(function () { return el(layer.path, "path", {class: "mf-path"}); });
    }
    function mark(m) {
      // A mark without a point is only a button (many dotted poses would hide the figure).
      if (m[2] === null) return;
      var p = body(layer.mark, d.P, m[0], "mf-marked"), q = p[m[2]];
      // Labels right of the middle are written leftwards, so they stay inside the figure.
      var box = svg.viewBox.baseVal, left = q && q[0] > box.x + box.width / 2;
      if (q) el(layer.mark, "text", {x: q[0] + (left ? -u : u), y: q[1] - u, class: "mf-marktext",
                                     "text-anchor": left ? "end" : "start"}).textContent = m[1];
    }
    stills();
    // api: the hooks of a live figure (book/_static/mech/live.js)
    var api = {data: d, svg: svg, place: place, frame: function () { return +div.getAttribute("data-frame") || 0; },
               redraw: function () { stills(); draw(api.frame()); }};
    function draw(f) {
      ["ghost", "link", "top"].forEach(function (k) { layer[k].textContent = ""; });
      if (d.ghost) body(layer.ghost, d.ghost, f, "mf-ghost");
      var p = body(layer.link, d.P, f, "mf-link");
      d.trace.forEach(function (i, k) {
        var done = []; for (var g = 0; g <= f; g++) done.push(at(d.P[i], g, 2));
        trace[k].setAttribute("d", pathD(done));
      });
      // A block is a box along the line to its second point (or level without one).
      d.blocks.forEach(function (b) {
        var q = p[b[0]], r = b[1] < 0 ? null : p[b[1]];
        if (!q || (b[1] >= 0 && !r)) return;
        var deg = r ? Math.atan2(r[1] - q[1], r[0] - q[0]) * 180 / Math.PI : 0;
        el(layer.top, "rect", {x: q[0] - 1.3 * u, y: q[1] - 0.8 * u, width: 2.6 * u, height: 1.6 * u, class: "mf-block",
                               transform: "rotate(" + deg.toFixed(1) + " " + q[0] + " " + q[1] + ")"});
      });
      var placed = [];
      if (!api.quick) layer.mark.querySelectorAll("text").forEach(function (t) { var b = t.getBBox(); if (b.width) placed.push(b); });
      p.forEach(function (q, i) {
        if (!q) return;
        // Names starting with "_" are helper points (a block's direction): not drawn.
        if (d.names[i].charAt(0) === "_") return;
        if (d.ground.indexOf(i) >= 0) {
          el(layer.top, "path", {d: pathD([q, [q[0] - u, q[1] + 1.7 * u], [q[0] + u, q[1] + 1.7 * u]], true), class: "mf-ground"});
        }
        el(layer.top, "circle", {cx: q[0], cy: q[1], r: 0.45 * u, class: "mf-joint"});
        if (d.labels) {
          var t = el(layer.top, "text", {x: q[0] + 0.7 * u, y: q[1] - 0.7 * u, class: "mf-label"});
          t.textContent = d.names[i];
          api.place(t, q, 0.7 * u, placed, i);
        }
      });
      if (api.after) api.after(f);
    }
    controls(div, d, draw);
    live(div, d, api);
  }

  // 3-D figure: orthographic view turned by yaw (about z) and pitch; drag to turn.
  // The scene's radius R is drawn as 1000 user units.
  function view3d(div, d) {
    var svg = div.querySelector("svg"), s = d.step, g = el(svg, "g", {}), K = 1000 / d.R;
    var yaw = +div.getAttribute("data-yaw") * Math.PI / 180,
        pitch = +div.getAttribute("data-pitch") * Math.PI / 180, frame = 0;
    // Screen x, screen y (down) and depth (towards the reader) of a point.
    function project(p) {
      var cy = Math.cos(yaw), sy = Math.sin(yaw), cp = Math.cos(pitch), sp = Math.sin(pitch);
      var x = cy * p[0] + sy * p[1], y = -sy * p[0] + cy * p[1], z = p[2];
      return [K * x, -K * (sp * y + cp * z), -(cp * y - sp * z)];
    }
    function xyz(arr, f) { var p = at(arr, f, 3); return p && [p[0] * s, p[1] * s, p[2] * s]; }
    // Great-circle arc between unit vectors (a link of a spherical linkage).
    function slerp(a, b) {
      var dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2], w = Math.acos(Math.max(-1, Math.min(1, dot))), out = [];
      for (var k = 0; k <= 24; k++) {
        var t = k / 24, sw = Math.sin(w) || 1, fa = w ? Math.sin((1 - t) * w) / sw : 1 - t, fb = w ? Math.sin(t * w) / sw : t;
        out.push([fa * a[0] + fb * b[0], fa * a[1] + fb * b[1], fa * a[2] + fb * b[2]]);
      }
      return out;
    }
    // On a sphere, the parts behind it are drawn faint and dashed: split by depth.
    function line(pts, cls) {
      var part = [[], []], prev = null, side = -1;
      pts.forEach(function (p) {
        p = p && project(p);
        if (prev && p) {
          var s2 = d.sphere && prev[2] + p[2] < 0 ? 1 : 0;
          if (s2 !== side) part[s2].push(null, prev);
          part[s2].push(p);
          side = s2;
        } else side = -1;
        prev = p;
      });
      el(g, "path", {d: pathD(part[1]), class: cls + " mf-back"});
      el(g, "path", {d: pathD(part[0]), class: cls});
    }
    function draw(f) {
      frame = f;
      g.textContent = "";
      if (d.sphere) el(g, "circle", {cx: 0, cy: 0, r: K, class: "mf-outline"});
      d.still.forEach(function (c) {
        var pts = []; for (var k = 0; k < c.p.length / 3; k++) pts.push(xyz(c.p, k));
        line(pts, c.c);
      });
      var p = d.names.map(function (_, i) { return xyz(d.P[i], f); });
      d.trace.forEach(function (i, k) {
        var all = [], done = [];
        for (var h = 0; h < d.n; h++) { all.push(xyz(d.P[i], h)); if (h <= f) done.push(all[h]); }
        // a live figure's finer curve (grid units, as d.P)
        if (d.curves && d.curves[k]) all = d.curves[k].map(function (q) { return q && q.map(function (v) { return v * s; }); });
        line(all, "mf-path-all");
        line(done, "mf-path");
      });
      d.links.forEach(function (l) {
        var a = p[l[0]], b = p[l[1]];
        if (a && b) line(l[2] ? slerp(a, b) : [a, b], "mf-link");
      });
      var placed = [];
      p.forEach(function (q, i) {
        if (!q) return;
        var r = project(q);
        el(g, "circle", {cx: r[0], cy: r[1], r: 18, class: "mf-joint" + (d.sphere && r[2] < 0 ? " mf-back" : "")});
        if (d.labels) {
          var t = el(g, "text", {x: r[0] + 30, y: r[1] - 30, class: "mf-label3"});
          t.textContent = d.names[i];
          api.place(t, r, 30, placed, i);
        }
      });
      if (api.after) api.after(f);
    }
    var api = {data: d, svg: svg, place: place, project: project, frame: function () { return frame; },
               redraw: function () { draw(frame); }, view: function () { return [yaw, pitch, K]; }};
    var drag = null;
    svg.addEventListener("pointerdown", function (e) {
      drag = [e.clientX, e.clientY];
      if (svg.setPointerCapture && e.pointerId !== undefined) { try { svg.setPointerCapture(e.pointerId); } catch (err) {} }
      e.preventDefault();
    });
    svg.addEventListener("pointermove", function (e) {
      if (!drag) return;
      // Half a degree per pixel; pitch stops at the poles so "up" never flips.
      yaw -= (e.clientX - drag[0]) * Math.PI / 360;
      pitch = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, pitch + (e.clientY - drag[1]) * Math.PI / 360));
      drag = [e.clientX, e.clientY];
      div.setAttribute("data-yaw", (yaw * 180 / Math.PI).toFixed(1));
      div.setAttribute("data-pitch", (pitch * 180 / Math.PI).toFixed(1));
      draw(frame);
    });
    ["pointerup", "pointercancel"].forEach(function (t) { svg.addEventListener(t, function () { drag = null; }); });
    if (d.n > 1) controls(div, d, draw); else draw(0);
    live(div, d, api);
  }

  // A live figure (d.live) loads the page's kernels and their controls as ES modules, once
  // per page and only on pages that have one; the drawing above is the build's own state.
  function live(div, d, api) {
    if (!d.live || d.live.type === "none") return;
    var root = document.documentElement.getAttribute("data-content_root");
    // not a page of the book (a notebook): the figure stays a recording
    if (root === null) return;
    import(root + "_static/mech/live.js").then(function (m) { m.attach(div, d, api); });
  }

  function scan() {
    document.querySelectorAll(".mech-fig:not([data-ready])").forEach(function (div) {
      div.setAttribute("data-ready", "1");
      var d = JSON.parse(div.querySelector("script.mech-data").textContent);
      (d.kind === "3d" ? view3d : planar)(div, d);
    });
  }
  window.mechFig = {scan: scan};
  scan();
})();
