/* sightline 3D replay, part 3 of 3 (experiments/replay.h): the page: sections, the URL
 * fragment, lazy building. Needs three.js r111 (global THREE) and its OrbitControls
 * (THREE.OrbitControls), both from Debian's libjs-three, and parts.js and scene_view.js
 * (experiments/CMakeLists.txt joins the three files in that order), loaded before this.
 *
 * DOM contract (scripts that check the page in a browser rely on it; docs/EXPERIMENTS.md):
 *  - Each scene: <section class="replay" data-scene="SCENE_ID" data-runs="RUN_ID RUN_ID ...">
 *    holding its data (<script type="application/json" class="replay-data">, or data-src =
 *    a .js file beside the page that sets window.sightlineReplayData[SCENE_ID]), and the
 *    first section on a level also holds the level (script.replay-level, see Data).
 *  - Built lazily (scrolled into view, clicked, or asked for by the fragment), it holds:
 *    canvas.replay-world (orbit view), canvas.replay-camera[data-slot=a] (main camera of the
 *    selected run) and canvas.replay-camera[data-slot=b] (second run, side-by-side mode),
 *    select.replay-run, input.replay-sbs + select.replay-run-b, button.replay-play,
 *    button.replay-back, button.replay-forward, select.replay-speed, input.replay-scrub,
 *    canvas.replay-marks (cuts: dark ticks; hidden look-at frames: red), span.replay-time,
 *    a.replay-link (href: the fragment that reopens the current run and time).
 *  - After every drawn frame the section carries data-run, data-frame, data-t and
 *    data-hidden ("1" when the independent check hides the look-at point at that frame),
 *    and data-run-b / data-frame-b in side-by-side mode.
 *  - The character is the only magenta (#ff00ff) object, drawn unlit (MeshBasicMaterial);
 *    the main-camera canvases have no antialiasing, fog or tone mapping, so its pixels are
 *    exactly #ff00ff. Vertical field of view: the scene data's fov (60 degrees, as the
 *    report's ray-cast pictures).
 *  - URL fragment: #run=RUN_ID&t=SECONDS (#t=SECONDS alone: the first run of the first
 *    scene; &run2=RUN_ID adds a second run side by side) builds that scene, scrolls to it and
 *    opens paused at that time. &panel=camera shows only that run's main-camera canvas,
 *    filling the window; &panel=world likewise the orbit view.
 *  - document.documentElement.dataset.replay: "ready" once the view the fragment asked for
 *    has drawn its frame (at once without a fragment); "error" after a JavaScript error or a
 *    fragment naming no run on the page (dataset.replayError says what).
 *
 * Data (one JSON object per scene, numbers in base64 little-endian typed arrays):
 *  bounds [[min],[max]], fov, character {size, look_at_height}, boxes (Float32, 6 per box:
 *  min xyz, max xyz), areas (same) + area_kinds ("e"/"s" per area), level null or {key,
 *  triangles}: the triangles are once per page in script.replay-level[data-level=KEY]
 *  (JSON {positions Float32 xyz, indices Uint16/Uint32 (index_type), triangles}, or data-src
 *  naming a .js beside the page that sets window.sightlineReplayLevels[KEY]), movers [{name,
 *  size, keys [[t,x,y,z]...]}] (base centre, linear between keys, held outside), runs [{id,
 *  label, frames, track (Float32 t,x,y,z,yaw per frame) or track_of (index of the run whose
 *  track is the same), camera_q, target_q (Uint16 xyz per frame on the scene's grid {origin,
 *  step}: metres = origin + q * step), flags (Uint8: 1 cut, 2 hidden)}].
 */
(function (NS) {
  'use strict';
  var root = document.documentElement, fail = NS.fail, Replay = NS.Replay, replays = [];

  function parseFragment() {
    var out = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
      if (!kv) return;
      var i = kv.indexOf('=');
      out[decodeURIComponent(i < 0 ? kv : kv.slice(0, i))] = i < 0 ? '' : decodeURIComponent(kv.slice(i + 1));
    });
    return out;
  }
  function findRun(id) {
    for (var i = 0; i < replays.length; ++i) {
      var k = replays[i].runIds.indexOf(id);
      if (k >= 0) return { replay: replays[i], index: k };
    }
    return null;
  }
  function applyFragment() {
    var f = parseFragment();
    root.classList.remove('replay-solo');
    Array.prototype.forEach.call(document.querySelectorAll('.replay-solo-target'), function (e) {
      e.classList.remove('replay-solo-target');
    });
    if (f.run === undefined && f.t === undefined && f.panel === undefined) {
      root.dataset.replay = 'ready';
      return;
    }
    delete root.dataset.replay;
    var target = f.run !== undefined ? findRun(f.run)
                                     : (replays.length && replays[0].runIds.length ? { replay: replays[0], index: 0 } : null);
    if (!target) return fail(f.run !== undefined ? 'no run ' + f.run + ' on this page' : 'no replay on this page');
    var r = target.replay, b = -1;
    if (f.run2 !== undefined) {
      b = r.runIds.indexOf(f.run2);
      if (b < 0) return fail('no run ' + f.run2 + ' in the scene of ' + r.runIds[target.index]);
    }
    var t = f.t !== undefined ? parseFloat(f.t) : 0;
    if (!isFinite(t)) return fail('t=' + f.t + ' is not a number');
    r.runA = target.index; r.runB = b; r.time = t;
    r.build(function () {
      r.setPlaying(false);
      r.selectRuns(target.index, b, true);
      r.time = t;
      if (f.panel === 'camera' || f.panel === 'world') {
        root.classList.add('replay-solo');
        (f.panel === 'camera' ? r.ui.panel.a.canvas : r.ui.world).classList.add('replay-solo-target');
      } else if (f.panel !== undefined) {
        return fail('panel=' + f.panel + ': expected camera or world');
      }
      r.resize();
      r.draw();
      // A solo canvas is fixed to the window: the page stays at the top (a scrolled page
      // also confuses headless Chromium's --screenshot).
      if (root.classList.contains('replay-solo')) window.scrollTo(0, 0);
      else r.section.scrollIntoView({ block: 'start' });
      // Drawn (preserveDrawingBuffer keeps it); ready after the next frame, or a moment,
      // whichever comes first: headless browsers give few animation frames.
      var marked = false, mark = function () {
        if (!marked && root.dataset.replay !== 'error') root.dataset.replay = 'ready';
        marked = true;
      };
      requestAnimationFrame(function () { requestAnimationFrame(mark); });
      setTimeout(mark, 50);
    });
  }

  function init() {
    if (typeof THREE === 'undefined' || !THREE.OrbitControls) return fail('three.js is not loaded');
    Array.prototype.forEach.call(document.querySelectorAll('section.replay'), function (s) {
      var r = new Replay(s);
      replays.push(r);
      var ph = s.querySelector('.replay-placeholder');
      if (ph) ph.addEventListener('click', function () { r.build(); });
    });
    if ('IntersectionObserver' in window) {
      var io = new IntersectionObserver(function (entries) {
        entries.forEach(function (e) {
          if (!e.isIntersecting) return;
          var r = replays.filter(function (x) { return x.section === e.target; })[0];
          if (r && !r.built) r.build();
        });
      }, { rootMargin: '200px' });
      replays.forEach(function (r) { io.observe(r.section); });
    }
    window.addEventListener('resize', function () {
      replays.forEach(function (r) { if (r.built) { r.resize(); r.draw(); } });
    });
    window.addEventListener('hashchange', applyFragment);
    applyFragment();
  }
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', init);
  else init();
})(window.SightlineReplay);
