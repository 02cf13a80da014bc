/* sightline 3D replay, part 2 of 3 (experiments/replay.h; the DOM contract is at the top of
 * replay.js): one scene's replay: its data, its UI, its three.js scene, renderers and
 * timeline. Built lazily, released when too many scenes hold WebGL contexts. */
(function (NS) {
  'use strict';
  var P = NS.parts, fail = NS.fail, bytes = P.bytes, f32 = P.f32, u16 = P.u16, u32 = P.u32;
  var dequantise = P.dequantise, el = P.el, helper = P.helper, boxesGeometry = P.boxesGeometry;
  var wireBox = P.wireBox, line = P.line, points = P.points, frustum = P.frustum;
  var moverPosition = P.moverPosition, disposeTree = P.disposeTree;
  var LAYER_HELPERS = P.LAYER_HELPERS;
  var MAGENTA = 0xff00ff;
  var SLOT_COLOURS = { a: 0xe8590c, b: 0x1c7ed6 };
  var MAX_BUILT = 4;  // WebGL contexts are limited (about 16 in Chromium): 3 per scene

  // ---- one scene's replay -------------------------------------------------------------
  function Replay(section) {
    this.section = section;
    this.id = section.dataset.scene;
    this.runIds = (section.dataset.runs || '').split(' ').filter(Boolean);
    this.data = null;
    this.built = false;
    this.building = false;
    this.runA = 0; this.runB = -1;
    this.time = 0; this.speed = 1; this.playing = false;
    this.onBuilt = [];
  }
  function loadScript(src, onload, onerror) {
    var tag = document.createElement('script');
    tag.src = src;
    tag.onload = onload;
    tag.onerror = onerror;
    document.head.appendChild(tag);
  }
  Replay.prototype.load = function (done) {
    var self = this, s = this.section;
    if (this.data) return done();
    var withLevel = function (raw) {
      self.loadLevel(raw.level, function (level) {
        raw.levelData = level;
        self.data = self.decode(raw);
        done();
      });
    };
    var inline = s.querySelector('script.replay-data');
    if (inline) return withLevel(JSON.parse(inline.textContent));
    var store = window.sightlineReplayData || {};
    if (store[this.id]) return withLevel(store[this.id]);
    loadScript(s.dataset.src, function () {
      var d = (window.sightlineReplayData || {})[self.id];
      if (!d) return self.showError('the data file ' + s.dataset.src + ' holds no scene ' + self.id);
      withLevel(d);
    }, function () { self.showError('cannot load ' + s.dataset.src + ' (kept beside the report?)'); });
  };
  // A level's triangles are on the page once (script.replay-level[data-level=KEY], inline or
  // naming a file beside the page), whichever scene wrote them.
  Replay.prototype.loadLevel = function (ref, done) {
    var self = this, store = window.sightlineReplayLevels = window.sightlineReplayLevels || {};
    if (!ref) return done(null);
    if (store[ref.key]) return done(store[ref.key]);
    var tag = document.querySelector('script.replay-level[data-level="' + ref.key + '"]');
    if (!tag) return this.showError('the level ' + ref.key + ' is not on this page');
    if (!tag.dataset.src) { store[ref.key] = JSON.parse(tag.textContent); return done(store[ref.key]); }
    loadScript(tag.dataset.src, function () {
      if (!store[ref.key]) return self.showError(tag.dataset.src + ' holds no level ' + ref.key);
      done(store[ref.key]);
    }, function () { self.showError('cannot load ' + tag.dataset.src + ' (kept beside the report?)'); });
  };
  Replay.prototype.decode = function (d) {
    d.boxArray = f32(d.boxes);
    d.areaArray = f32(d.areas);
    d.runs.forEach(function (r) {
      r.cam = dequantise(r.camera_q, d.grid); r.tgt = dequantise(r.target_q, d.grid); r.flag = bytes(r.flags);
      if (r.track) r.trk = f32(r.track);
      if (r.lens) r.lns = f32(r.lens);  // fov, roll per frame (degrees)
    });
    d.runs.forEach(function (r) { if (!r.trk) r.trk = d.runs[r.track_of].trk; });
    return d;
  };
  Replay.prototype.showError = function (message) {
    var p = this.section.querySelector('.replay-error') || el('p', 'replay-error', this.section);
    p.textContent = 'Replay: ' + message;
    fail(message);
  };
  // Largest frame whose time is <= t (within a little for Float32 times), clamped.
  Replay.prototype.frameAt = function (run, t) {
    var trk = run.trk, lo = 0, hi = run.frames - 1;
    if (hi < 0) return 0;
    while (lo < hi) {
      var mid = (lo + hi + 1) >> 1;
      if (trk[mid * 5] <= t + 1e-4) lo = mid; else hi = mid - 1;
    }
    return lo;
  };
  Replay.prototype.build = function (done) {
    var self = this;
    if (done) this.onBuilt.push(done);
    if (this.built) return this.flushBuilt();
    if (this.building) return;
    this.building = true;
    this.load(function () {
      try {
        self.buildNow();
      } catch (e) {
        self.building = false;
        self.showError(e.message || e);
        return;
      }
      self.building = false;
      self.built = true;
      Replay.noteBuilt(self);
      self.flushBuilt();
    });
  };
  Replay.prototype.flushBuilt = function () {
    var list = this.onBuilt;
    this.onBuilt = [];
    this.draw();
    list.forEach(function (f) { f(); });
  };

  Replay.prototype.buildNow = function () {
    var self = this, d = this.data, s = this.section;
    var ph = s.querySelector('.replay-placeholder');
    if (ph) ph.hidden = true;
    var ui = this.ui = el('div', 'replay-ui', s);
    var bar = el('div', 'replay-bar', ui);
    var l1 = el('label', '', bar, 'run ');
    ui.run = el('select', 'replay-run', l1);
    var l2 = el('label', '', bar);
    ui.sbs = el('input', 'replay-sbs', l2); ui.sbs.type = 'checkbox';
    l2.appendChild(document.createTextNode(' side by side with '));
    ui.runB = el('select', 'replay-run-b', l2);
    var l3 = el('label', '', bar);
    ui.follow = el('input', 'replay-follow', l3); ui.follow.type = 'checkbox';
    l3.appendChild(document.createTextNode(' orbit follows the character'));
    var l4 = el('label', '', bar);
    ui.cutaway = el('input', 'replay-cutaway', l4); ui.cutaway.type = 'checkbox';
    ui.cutaway.checked = !!d.level;  // a level's ceilings hide the character from the orbit view
    l4.appendChild(document.createTextNode(' cut away above the camera'));
    d.runs.forEach(function (r, i) {
      el('option', '', ui.run, r.label).value = i;
      el('option', '', ui.runB, r.label).value = i;
    });
    ui.run.value = this.runA;
    ui.runB.value = this.runB >= 0 ? this.runB : Math.min(1, d.runs.length - 1);
    ui.sbs.checked = this.runB >= 0;

    var views = el('div', 'replay-views', ui);
    ui.world = el('canvas', 'replay-world', views);
    ui.world.setAttribute('aria-label', '3D view of the scene, the character and the camera');
    var panels = el('div', 'replay-panels', views);
    ui.panel = {};
    ['a', 'b'].forEach(function (slot) {
      var p = el('div', 'replay-panel', panels);
      p.dataset.slot = slot;
      var label = el('div', 'replay-panel-label', p);
      var c = el('canvas', 'replay-camera', p);
      c.setAttribute('aria-label', 'what the main camera sees');
      c.dataset.slot = slot;
      // A tracking shot's composition (thirds, framed rectangles, screen positions) over it.
      var overlay = d.shot ? el('canvas', 'replay-overlay', p) : null;
      ui.panel[slot] = { box: p, label: label, canvas: c, overlay: overlay };
    });
    el('div', 'replay-legend', ui, 'Magenta: the character; yellow: the look-at point with the ' +
       'sight line (green visible, red hidden by the independent check); orange / blue: the ' +
       'camera and its path; red dots: frames with the look-at point hidden; dark dots: cuts. ' +
       'Drag to orbit, right-drag to pan, wheel to zoom, double-click to come back to the ' +
       'character. Keys: space play, arrows step.');

    var tl = el('div', 'replay-timeline', ui);
    ui.back = el('button', 'replay-back', tl, '\u25c0 frame');
    ui.play = el('button', 'replay-play', tl, '\u25b6 play');
    ui.forward = el('button', 'replay-forward', tl, 'frame \u25b6');
    ui.speed = el('select', 'replay-speed', tl);
    [0.25, 0.5, 1, 2, 4].forEach(function (v) { el('option', '', ui.speed, v + 'x').value = v; });
    ui.speed.value = String(this.speed);
    var sb = el('div', 'replay-scrub-box', tl);
    ui.scrub = el('input', 'replay-scrub', sb); ui.scrub.type = 'range'; ui.scrub.min = 0; ui.scrub.step = 1;
    ui.marks = el('canvas', 'replay-marks', sb);
    ui.shots = el('canvas', 'replay-shots', sb);  // an edited film's shots, one band each
    ui.time = el('span', 'replay-time', tl);
    ui.link = el('a', 'replay-link', tl, 'link to this moment');
    ui.link.title = 'a link that opens this run paused at this time';

    // three.js: one scene graph; the main-camera panels see layer 0 only.
    var scene = this.scene = new THREE.Scene();
    scene.background = new THREE.Color(0xd0d7de);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8a8a, 0.75));
    var sun = new THREE.DirectionalLight(0xffffff, 0.45);
    sun.position.set(0.4, 1, 0.25);
    scene.add(sun);
    var lo = d.bounds[0], hi = d.bounds[1];
    var centre = new THREE.Vector3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
    var diag = Math.max(1, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
    if (d.boxArray.length) {
      scene.add(new THREE.Mesh(boxesGeometry(d.boxArray), new THREE.MeshLambertMaterial({ color: 0xa39a8c })));
    }
    if (d.levelData) {
      var lv = d.levelData, g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(f32(lv.positions), 3));
      g.setIndex(new THREE.BufferAttribute(lv.index_type === 'u16' ? u16(lv.indices) : u32(lv.indices), 1));
      var flat = g.toNonIndexed();  // flat shading: one normal per triangle
      g.dispose();
      flat.computeVertexNormals();
      scene.add(new THREE.Mesh(flat, new THREE.MeshLambertMaterial({ color: 0x9c9890, side: THREE.DoubleSide })));
    } else {
      // Box scenes stand on the ground y = 0, as in the report's ray-cast pictures.
      var size = Math.ceil(diag * 1.5);
      var ground = new THREE.Mesh(new THREE.PlaneBufferGeometry(size, size),
                                  new THREE.MeshLambertMaterial({ color: 0xc9c4b5, polygonOffset: true,
                                                                  polygonOffsetFactor: 1, polygonOffsetUnits: 1 }));
      ground.rotation.x = -Math.PI / 2;  // pushed back in depth so the grid lines on it win
      ground.position.set(centre.x, 0, centre.z);
      scene.add(ground);
      var grid = new THREE.GridHelper(size, Math.min(400, size), 0x8d877b, 0xaaa494);
      grid.position.set(centre.x, 0, centre.z);
      scene.add(grid);
    }
    for (var i = 0; i < d.area_kinds.length; ++i) {
      var a = d.areaArray;
      scene.add(helper(wireBox([a[i * 6], a[i * 6 + 1], a[i * 6 + 2]], [a[i * 6 + 3], a[i * 6 + 4], a[i * 6 + 5]],
                               d.area_kinds[i] === 'e' ? 0x2f9e44 : 0x0c8599)));
    }
    this.movers = d.movers.map(function (m) {
      var mesh = new THREE.Mesh(new THREE.BoxBufferGeometry(m.size[0], m.size[1], m.size[2]).translate(0, m.size[1] / 2, 0),
                                new THREE.MeshLambertMaterial({ color: 0x4c6e96 }));
      scene.add(mesh);
      return { keys: m.keys, mesh: mesh };
    });
    var cs = d.character.size;
    this.character = new THREE.Mesh(new THREE.BoxBufferGeometry(cs[0], cs[1], cs[2]).translate(0, cs[1] / 2, 0),
                                     new THREE.MeshBasicMaterial({ color: MAGENTA }));
    scene.add(this.character);
    this.facing = helper(new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), Math.max(0.8, cs[1] * 0.6), 0x1864ab));
    scene.add(this.facing);
    this.slots = {};

    this.worldCamera = new THREE.PerspectiveCamera(50, 1.6, diag / 2000, diag * 20);
    this.worldCamera.layers.enable(LAYER_HELPERS);
    this.worldCamera.position.copy(centre).add(new THREE.Vector3(0.45, 0.6, 0.75).multiplyScalar(diag * 0.8));
    this.renderers = {};
    this.cutPlane = new THREE.Plane(new THREE.Vector3(0, -1, 0), 0);  // keeps y <= constant
    this.renderers.world = new THREE.WebGLRenderer({ canvas: ui.world, antialias: true, preserveDrawingBuffer: true });
    this.controls = new THREE.OrbitControls(this.worldCamera, ui.world);
    this.controls.target.copy(centre);
    this.controls.update();
    this.controls.addEventListener('change', function () { self.drawWorld(); });
    this.panelCameras = {};
    ['a', 'b'].forEach(function (slot) {
      self.panelCameras[slot] = new THREE.PerspectiveCamera(d.fov, 1.6, 0.05, diag * 20);
      self.renderers[slot] = new THREE.WebGLRenderer({ canvas: ui.panel[slot].canvas, antialias: false, preserveDrawingBuffer: true });
      self.renderers[slot].setPixelRatio(1);  // exact pixels for checks
    });
    this.resize();

    ui.run.onchange = function () { self.selectRuns(+ui.run.value, self.runB); };
    ui.runB.onchange = function () { if (ui.sbs.checked) self.selectRuns(self.runA, +ui.runB.value); };
    ui.sbs.onchange = function () { self.selectRuns(self.runA, ui.sbs.checked ? +ui.runB.value : -1); };
    ui.follow.onchange = function () { self.draw(); };
    ui.cutaway.onchange = function () { self.draw(); };
    ui.play.onclick = function () { self.setPlaying(!self.playing); };
    ui.back.onclick = function () { self.step(-1); };
    ui.forward.onclick = function () { self.step(1); };
    ui.speed.onchange = function () { self.speed = +ui.speed.value; };
    ui.scrub.oninput = function () { self.setPlaying(false); self.seekFrame(+ui.scrub.value); };
    s.tabIndex = 0;
    s.addEventListener('keydown', function (e) {
      if (e.target.tagName === 'SELECT' || e.target.tagName === 'INPUT') return;
      if (e.key === ' ') { self.setPlaying(!self.playing); e.preventDefault(); }
      if (e.key === 'ArrowLeft') { self.step(-1); e.preventDefault(); }
      if (e.key === 'ArrowRight') { self.step(1); e.preventDefault(); }
    });
    this.selectRuns(this.runA, this.runB, true);
    // A level is big: start close to the character (double-click the view to come back).
    if (d.level) this.frameCharacter();
    ui.world.addEventListener('dblclick', function () { self.frameCharacter(); });
  };
  Replay.prototype.frameCharacter = function () {
    var p = this.character.position.clone().add(new THREE.Vector3(0, this.data.character.size[1] / 2, 0));
    this.controls.target.copy(p);
    this.worldCamera.position.copy(p).add(new THREE.Vector3(0.45, 0.6, 0.75).multiplyScalar(12));
    this.controls.update();
    this.draw();
  };

  // The helpers of one run in one slot: camera path, hidden and cut markers, frustum,
  // look-at point and sight line, character path.
  Replay.prototype.makeSlot = function (slot, index) {
    var old = this.slots[slot];
    if (old) { this.scene.remove(old.group); disposeTree(old.group); }
    if (index < 0) { delete this.slots[slot]; return; }
    var run = this.data.runs[index], n = run.frames, colour = SLOT_COLOURS[slot];
    var group = new THREE.Group();
    group.add(line(run.cam, colour));
    var trackPts = new Float32Array(n * 3), hid = [], cut = [];
    for (var i = 0; i < n; ++i) {
      trackPts[i * 3] = run.trk[i * 5 + 1]; trackPts[i * 3 + 1] = run.trk[i * 5 + 2] + 0.02; trackPts[i * 3 + 2] = run.trk[i * 5 + 3];
      var c = [run.cam[i * 3], run.cam[i * 3 + 1], run.cam[i * 3 + 2]];
      if (run.flag[i] & 2) hid.push.apply(hid, c);
      if (run.flag[i] & 1) cut.push.apply(cut, c);
    }
    group.add(line(trackPts, 0x0b7285));
    if (hid.length) group.add(points(new Float32Array(hid), 0xe03131, 4));
    if (cut.length) group.add(points(new Float32Array(cut), 0x212529, 9));
    var fr = frustum(this.data.fov, colour);
    group.add(fr);
    var look = new THREE.Mesh(new THREE.SphereBufferGeometry(0.08, 10, 8), new THREE.MeshBasicMaterial({ color: 0xfab005 }));
    group.add(look);
    var sightGeom = new THREE.BufferGeometry();
    sightGeom.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    var sight = new THREE.Line(sightGeom, new THREE.LineBasicMaterial({ color: 0x2f9e44 }));
    group.add(sight);
    helper(group);
    this.scene.add(group);
    this.slots[slot] = { run: run, index: index, group: group, frustum: fr, look: look, sight: sight };
  };
  Replay.prototype.selectRuns = function (a, b, keepTime) {
    var ui = this.ui;
    this.runA = a; this.runB = b;
    ui.run.value = a;
    ui.sbs.checked = b >= 0;
    if (b >= 0) ui.runB.value = b;
    this.makeSlot('a', a);
    this.makeSlot('b', b);
    ui.panel.b.box.hidden = b < 0;
    var run = this.data.runs[a];
    ui.scrub.max = Math.max(0, run.frames - 1);
    if (!keepTime) this.time = Math.min(this.time, run.frames ? run.trk[(run.frames - 1) * 5] : 0);
    this.resize();
    this.drawMarks();
    this.draw();
  };
  Replay.prototype.drawMarks = function () {
    var c = this.ui.marks, run = this.data.runs[this.runA], n = run.frames;
    var w = c.width = Math.max(1, c.clientWidth), h = c.height = Math.max(1, c.clientHeight);
    var g = c.getContext('2d');
    g.clearRect(0, 0, w, h);
    g.fillStyle = '#e9ecef';
    g.fillRect(0, 0, w, h);
    for (var i = 0; i < n; ++i) {
      var x = n > 1 ? i / (n - 1) * (w - 1) : 0;
      if (run.flag[i] & 2) { g.fillStyle = '#e03131'; g.fillRect(x, h / 2, Math.max(1, w / n), h / 2); }
      if (run.flag[i] & 1) { g.fillStyle = '#212529'; g.fillRect(x, 0, 2, h); }
    }
    this.drawShots(run);
  };
  // The timeline of an edited film's shots: a band per shot, coloured by its name, labelled.
  Replay.prototype.drawShots = function (run) {
    var c = this.ui.shots, shots = run.shots || [], n = run.frames;
    c.style.display = shots.length ? 'block' : 'none';
    if (!shots.length) return;
    var w = c.width = Math.max(1, c.clientWidth), h = c.height = Math.max(1, c.clientHeight);
    var g = c.getContext('2d'), palette = ['#a5d8ff', '#b2f2bb', '#ffec99', '#ffc9c9', '#d0bfff',
                                           '#99e9f2', '#ffd8a8', '#eebefa'];
    var colours = {};
    g.clearRect(0, 0, w, h);
    g.font = '10px sans-serif';
    g.textBaseline = 'middle';
    for (var k = 0; k < shots.length; ++k) {
      var name = shots[k][0], from = shots[k][1], to = k + 1 < shots.length ? shots[k + 1][1] : n;
      if (!(name in colours)) colours[name] = palette[Object.keys(colours).length % palette.length];
      var x0 = n > 1 ? from / (n - 1) * (w - 1) : 0, x1 = n > 1 ? to / (n - 1) * (w - 1) : w;
      g.fillStyle = colours[name];
      g.fillRect(x0, 0, Math.max(1, x1 - x0), h);
      g.fillStyle = '#212529';
      g.fillRect(x0, 0, 1, h);
      g.save();
      g.beginPath(); g.rect(x0 + 2, 0, Math.max(0, x1 - x0 - 4), h); g.clip();
      g.fillText(name, x0 + 3, h / 2);
      g.restore();
    }
  };
  // Draws the shot's composition over a main-camera panel: the image the shot asks for (its
  // aspect, at the panel's height: the panel shows the frame's vertical extent), its thirds,
  // the framed rectangles (dashed) and the screen positions (crosses).
  Replay.prototype.drawComposition = function (slot) {
    var shot = this.data.shot, panel = this.ui.panel[slot];
    if (!shot || !panel || !panel.overlay) return;
    var c = panel.overlay, src = panel.canvas;
    var w = Math.max(1, src.clientWidth), h = Math.max(1, src.clientHeight);
    if (c.width !== w || c.height !== h) {  // laid out again only when the panel changed
      c.style.left = src.offsetLeft + 'px';
      c.style.top = src.offsetTop + 'px';
      c.style.width = w + 'px';
      c.style.height = h + 'px';
      c.width = w;
      c.height = h;
    }
    var g = c.getContext('2d');
    g.clearRect(0, 0, w, h);
    var scale = shot.aspect / (w / h);  // the shot's image is this much wider than the panel
    var X = function (sx) { return w / 2 + (sx - 0.5) * w * scale; };
    var Y = function (sy) { return h * (1 - sy); };
    g.strokeStyle = 'rgba(255,255,255,0.7)';
    g.lineWidth = 1;
    g.setLineDash([]);
    [1 / 3, 2 / 3].forEach(function (v) {
      g.beginPath(); g.moveTo(X(v), 0); g.lineTo(X(v), h); g.stroke();
      g.beginPath(); g.moveTo(X(0), Y(v)); g.lineTo(X(1), Y(v)); g.stroke();
    });
    g.strokeRect(X(0), Y(1), X(1) - X(0), Y(0) - Y(1));
    g.strokeStyle = 'rgba(25,113,194,0.9)';
    g.setLineDash([4, 3]);
    (shot.rects || []).forEach(function (r) {
      g.strokeRect(X(r[0]), Y(r[3]), X(r[2]) - X(r[0]), Y(r[1]) - Y(r[3]));
    });
    g.setLineDash([]);
    g.strokeStyle = 'rgba(224,49,49,0.95)';
    (shot.points || []).forEach(function (p) {
      var x = X(p[0]), y = Y(p[1]);
      g.beginPath(); g.moveTo(x - 5, y); g.lineTo(x + 5, y); g.moveTo(x, y - 5); g.lineTo(x, y + 5); g.stroke();
    });
  };

  // The name of the shot at a frame of an edited film, or ''.
  function shotAt(run, frame) {
    var shots = run.shots || [], name = '';
    for (var k = 0; k < shots.length && shots[k][1] <= frame; ++k) name = shots[k][0];
    return name;
  }
  Replay.prototype.setPlaying = function (on) {
    var self = this;
    if (on === this.playing) return;
    this.playing = on;
    this.ui.play.textContent = on ? '\u2016 pause' : '\u25b6 play';
    if (!on) return;
    var run = this.data.runs[this.runA], end = run.frames ? run.trk[(run.frames - 1) * 5] : 0;
    if (this.time >= end) this.time = run.frames ? run.trk[0] : 0;
    var last = null;
    function tick() {
      if (!self.playing || !self.built) return;
      var now = performance.now();
      if (last !== null) self.time += (now - last) / 1000 * self.speed;
      last = now;
      if (self.time >= end) { self.time = end; self.setPlaying(false); }
      self.draw();
      if (self.playing) schedule();
    }
    // requestAnimationFrame, with a timer in case frames do not come (a hidden tab, a
    // headless browser): playback goes on, less smoothly.
    function schedule() {
      var fired = false, once = function () { if (!fired) { fired = true; tick(); } };
      requestAnimationFrame(once);
      setTimeout(once, 100);
    }
    schedule();
  };
  Replay.prototype.seekFrame = function (frame) {
    var run = this.data.runs[this.runA];
    frame = Math.max(0, Math.min(run.frames - 1, frame));
    this.time = run.trk[frame * 5];
    this.draw();
  };
  Replay.prototype.step = function (delta) {
    this.setPlaying(false);
    this.seekFrame(this.frameAt(this.data.runs[this.runA], this.time) + delta);
  };
  Replay.prototype.resize = function () {
    if (!this.built && !this.building) return;
    var ui = this.ui, self = this;
    var fit = function (renderer, canvas, camera, ratio) {
      var w = Math.max(1, canvas.clientWidth), h = Math.max(1, canvas.clientHeight);
      renderer.setPixelRatio(ratio);
      renderer.setSize(w, h, false);
      camera.aspect = w / h;
      camera.updateProjectionMatrix();
    };
    fit(this.renderers.world, ui.world, this.worldCamera, window.devicePixelRatio || 1);
    ['a', 'b'].forEach(function (slot) { fit(self.renderers[slot], ui.panel[slot].canvas, self.panelCameras[slot], 1); });
  };

  // Places everything at the current time and draws the orbit view and the panels.
  Replay.prototype.draw = function () {
    if (!this.ui || !this.scene) return;
    var self = this, s = this.section, ui = this.ui, t = this.time;
    this.movers.forEach(function (m) {
      var p = moverPosition(m.keys, t);
      m.mesh.position.set(p[1], p[2], p[3]);
    });
    var state = {};
    ['a', 'b'].forEach(function (slot) {
      var sl = self.slots[slot];
      if (!sl) return;
      var run = sl.run, f = self.frameAt(run, t), cam = run.cam, tgt = run.tgt;
      var eye = new THREE.Vector3(cam[f * 3], cam[f * 3 + 1], cam[f * 3 + 2]);
      var at = new THREE.Vector3(tgt[f * 3], tgt[f * 3 + 1], tgt[f * 3 + 2]);
      var hidden = (run.flag[f] & 2) !== 0;
      sl.frustum.position.copy(eye);
      sl.frustum.lookAt(at);
      sl.look.position.copy(at);
      var sp = sl.sight.geometry.attributes.position;
      sp.setXYZ(0, eye.x, eye.y, eye.z); sp.setXYZ(1, at.x, at.y, at.z); sp.needsUpdate = true;
      sl.sight.geometry.computeBoundingSphere();
      sl.sight.material.color.setHex(hidden ? 0xe03131 : 0x2f9e44);
      var pc = self.panelCameras[slot];
      pc.position.copy(eye);
      pc.up.set(0, 1, 0);
      pc.lookAt(at);
      // A composing camera's own lens (FORMATS.md: roll turns the right axis toward up).
      var fov = run.lns && run.lns[f * 2] > 0 ? run.lns[f * 2] : self.data.fov;
      if (pc.fov !== fov) { pc.fov = fov; pc.updateProjectionMatrix(); }
      if (run.lns) pc.rotateZ(run.lns[f * 2 + 1] * Math.PI / 180);
      state[slot] = { run: run, frame: f, hidden: hidden };
      self.drawComposition(slot);
      var p = ui.panel[slot];
      p.box.classList.toggle('replay-hidden-frame', hidden);
      p.label.textContent = 'main camera: ' + run.label + (hidden ? ' \u2014 look-at point hidden' : '');
    });
    var a = state.a;
    if (!a) return;
    var moved = this.placeCharacter(a.run, a.frame);
    if (ui.follow.checked && moved) {
      this.worldCamera.position.add(moved);
      this.controls.target.add(moved);
      this.controls.update();
    }
    // The orbit view only: everything above the camera and the character's head is cut away.
    var top = Math.max(this.character.position.y + this.data.character.size[1], this.panelCameras.a.position.y) + 0.3;
    this.cutPlane.constant = top;
    this.renderers.world.clippingPlanes = ui.cutaway.checked ? [this.cutPlane] : [];
    this.renderers.world.render(this.scene, this.worldCamera);
    this.renderers.a.render(this.scene, this.panelCameras.a);
    if (state.b) {
      this.placeCharacter(state.b.run, state.b.frame);
      this.renderers.b.render(this.scene, this.panelCameras.b);
      this.placeCharacter(a.run, a.frame);
    }
    ui.scrub.value = a.frame;
    var run = a.run;
    ui.link.href = '#run=' + encodeURIComponent(run.id) + '&t=' + run.trk[a.frame * 5].toFixed(3) +
        (state.b ? '&run2=' + encodeURIComponent(state.b.run.id) : '');
    ui.time.textContent = 't = ' + run.trk[a.frame * 5].toFixed(2) + ' s, frame ' + a.frame + ' / ' +
        (run.frames - 1) + ((run.flag[a.frame] & 1) ? ', cut' : '') + (a.hidden ? ', look-at hidden' : '') +
        (run.shots ? ', shot: ' + shotAt(run, a.frame) : '');
    s.dataset.run = run.id;
    s.dataset.frame = a.frame;
    s.dataset.t = run.trk[a.frame * 5];
    s.dataset.hidden = a.hidden ? '1' : '0';
    if (state.b) { s.dataset.runB = state.b.run.id; s.dataset.frameB = state.b.frame; }
    else { delete s.dataset.runB; delete s.dataset.frameB; }
  };
  Replay.prototype.drawWorld = function () {
    if (this.renderers) this.renderers.world.render(this.scene, this.worldCamera);
  };
  // Puts the character at a run's frame; returns how far it moved.
  Replay.prototype.placeCharacter = function (run, f) {
    var k = run.trk, p = new THREE.Vector3(k[f * 5 + 1], k[f * 5 + 2], k[f * 5 + 3]);
    var moved = p.clone().sub(this.character.position);
    this.character.position.copy(p);
    var yaw = k[f * 5 + 4] * Math.PI / 180;
    this.facing.position.set(p.x, p.y + this.data.character.size[1] + 0.1, p.z);
    this.facing.setDirection(new THREE.Vector3(Math.sin(yaw), 0, Math.cos(yaw)));
    return moved;
  };
  // Frees the WebGL contexts and the UI (the page keeps only MAX_BUILT scenes built).
  Replay.prototype.release = function () {
    if (!this.built) return;
    this.setPlaying(false);
    var self = this;
    disposeTree(this.scene);
    this.controls.dispose();
    Object.keys(this.renderers).forEach(function (k) {
      self.renderers[k].dispose();
      self.renderers[k].forceContextLoss();
    });
    this.ui.parentNode.removeChild(this.ui);
    this.ui = null; this.scene = null; this.renderers = null; this.slots = {};
    this.built = false;
    var ph = this.section.querySelector('.replay-placeholder');
    if (ph) ph.hidden = false;
  };

  var builtOrder = [];
  Replay.noteBuilt = function (r) {
    builtOrder = builtOrder.filter(function (x) { return x !== r; });
    builtOrder.push(r);
    while (builtOrder.length > MAX_BUILT) builtOrder.shift().release();
  };

  NS.Replay = Replay;
})(window.SightlineReplay = window.SightlineReplay || {});
