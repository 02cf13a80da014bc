/* sightline 3D replay, part 1 of 3 (experiments/replay.h; the DOM contract is at the top of
 * replay.js): decoding the page's base64 buffers and building three.js objects, and the
 * page-wide error flag. Files are joined in order: parts.js, scene_view.js, replay.js. */
(function (NS) {
  'use strict';
  var root = document.documentElement;
  // document.documentElement.dataset.replay = "error" with what went wrong.
  NS.fail = function (message) {
    root.dataset.replay = 'error';
    root.dataset.replayError = String(message);
  };
  window.addEventListener('error', function (e) { NS.fail(e.message || 'error'); });
  window.addEventListener('unhandledrejection', function (e) { NS.fail(e.reason || 'rejection'); });

  var LAYER_HELPERS = 1;  // drawn in the orbit view only, never in the main-camera panels

  function bytes(b64) {
    var s = atob(b64), a = new Uint8Array(s.length);
    for (var i = 0; i < s.length; ++i) a[i] = s.charCodeAt(i);
    return a;
  }
  function f32(b64) { var a = bytes(b64); return new Float32Array(a.buffer, 0, a.length >> 2); }
  function u16(b64) { var a = bytes(b64); return new Uint16Array(a.buffer, 0, a.length >> 1); }
  function u32(b64) { var a = bytes(b64); return new Uint32Array(a.buffer, 0, a.length >> 2); }

  // Uint16 xyz triples on the scene's grid back to metres.
  function dequantise(b64, grid) {
    var q = u16(b64), out = new Float32Array(q.length), o = grid.origin, step = grid.step;
    for (var i = 0; i < q.length; ++i) out[i] = o[i % 3] + q[i] * step;
    return out;
  }
  function el(tag, cls, parent, text) {
    var e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function helper(obj) { obj.traverse(function (o) { o.layers.set(LAYER_HELPERS); }); return obj; }

  // Solid boxes as one mesh: 12 triangles each, flat normals.
  function boxesGeometry(b) {
    var n = b.length / 6, pos = new Float32Array(n * 108), nor = new Float32Array(n * 108), k = 0;
    var faces = [  // axis, side, the four corners' (u, v) over the other two axes
      [0, 0], [0, 1], [1, 0], [1, 1], [2, 0], [2, 1]];
    for (var i = 0; i < n; ++i) {
      var lo = [b[i * 6], b[i * 6 + 1], b[i * 6 + 2]], hi = [b[i * 6 + 3], b[i * 6 + 4], b[i * 6 + 5]];
      for (var f = 0; f < 6; ++f) {
        var ax = faces[f][0], side = faces[f][1], u = (ax + 1) % 3, v = (ax + 2) % 3;
        var corners = [[0, 0], [1, 0], [1, 1], [0, 0], [1, 1], [0, 1]];
        if (side === 0) corners = [[0, 0], [1, 1], [1, 0], [0, 0], [0, 1], [1, 1]];
        for (var c = 0; c < 6; ++c) {
          var p = [0, 0, 0];
          p[ax] = side ? hi[ax] : lo[ax];
          p[u] = corners[c][0] ? hi[u] : lo[u];
          p[v] = corners[c][1] ? hi[v] : lo[v];
          var q = [0, 0, 0];
          q[ax] = side ? 1 : -1;
          pos.set(p, k); nor.set(q, k); k += 3;
        }
      }
    }
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(nor, 3));
    return g;
  }
  function wireBox(lo, hi, colour) {
    var g = new THREE.BoxBufferGeometry(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    var e = new THREE.LineSegments(new THREE.EdgesGeometry(g), new THREE.LineBasicMaterial({ color: colour }));
    e.position.set((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    g.dispose();
    return e;
  }
  function line(points, colour) {
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(points, 3));
    return new THREE.Line(g, new THREE.LineBasicMaterial({ color: colour }));
  }
  function points(pts, colour, size) {
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pts, 3));
    return new THREE.Points(g, new THREE.PointsMaterial({ color: colour, size: size, sizeAttenuation: false }));
  }
  // The camera drawn as a small frustum: apex at the origin, opening along +z (Object3D.lookAt
  // turns +z toward the target for objects that are not cameras).
  function frustum(fov, colour) {
    var h = Math.tan(fov * Math.PI / 360) * 0.8, w = h * 1.6, d = 0.8;
    var c = [[-w, -h], [w, -h], [w, h], [-w, h]], v = [];
    for (var i = 0; i < 4; ++i) {
      var a = c[i], b = c[(i + 1) % 4];
      v.push(0, 0, 0, a[0], a[1], d, a[0], a[1], d, b[0], b[1], d);
    }
    var g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(v), 3));
    return new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: colour }));
  }
  function moverPosition(keys, t) {
    if (t <= keys[0][0]) return keys[0];
    for (var i = 1; i < keys.length; ++i) {
      if (t <= keys[i][0]) {
        var a = keys[i - 1], b = keys[i], s = (t - a[0]) / (b[0] - a[0]);
        return [t, a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]), a[3] + s * (b[3] - a[3])];
      }
    }
    return keys[keys.length - 1];
  }

  function disposeTree(obj) {
    obj.traverse(function (o) {
      if (o.geometry) o.geometry.dispose();
      if (o.material) o.material.dispose();
    });
  }

  NS.parts = {
    LAYER_HELPERS: LAYER_HELPERS, bytes: bytes, f32: f32, u16: u16, u32: u32, dequantise: dequantise,
    el: el, helper: helper, boxesGeometry: boxesGeometry, wireBox: wireBox, line: line,
    points: points, frustum: frustum, moverPosition: moverPosition, disposeTree: disposeTree
  };
})(window.SightlineReplay = window.SightlineReplay || {});
