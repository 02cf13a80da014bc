#!/usr/bin/env python3
"""Checks a sightline replay page (a suite's report.html or `sightline view`'s page) in a real
browser: headless Chromium with software WebGL (SwiftShader), driven over the DevTools
protocol on a pipe. Python 3 standard library only. scripts/check-replay.sh runs it; see
docs/REPLAY.md.

For one scene of the page it picks frames from the page's own data, whose hidden flags are
the independent check's (experiments/metrics.h, never a controller's flag), opens the page at
#run=ID&t=T&panel=camera|world, waits for document.documentElement.dataset.replay, takes a
screenshot and asserts:
  - no JavaScript error: no console.error / console.assert, no uncaught exception, no error
    entry in the browser log, and dataset.replay is "ready", never "error";
  - the page drew the frame asked for (the section's data-run, data-frame) and its
    data-hidden agrees with the data's flag;
  - panel=world: the 3D view is not blank (many colours, most pixels not the background);
  - panel=camera: the character's magenta (#ff00ff) is on screen at frames where the look-at
    point is visible, and nowhere at a frame where it is hidden (--hidden-run).
Exit status: 0 all passed, 1 a check failed, 2 bad usage or the browser did not work.
"""
import argparse
import base64
import fcntl
import json
import os
import queue
import re
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib
from html import unescape


# --- PNG decoding (what Chromium's screenshots use: 8-bit RGB or RGBA, non-interlaced) ---

def decode_png(data):
    """Returns (width, height, channels, rows): rows is a list of bytes, one per scanline,
    already unfiltered. Supports bit depth 8, colour types 0 (grey), 2 (RGB), 4 (grey+alpha),
    6 (RGBA); no interlacing."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, header = 8, [], None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        raise ValueError("PNG without IHDR")
    width, height, depth, colour, _, _, interlace = header
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace != 0:
        raise ValueError("unsupported PNG (depth %d, colour type %d, interlace %d)"
                         % (depth, colour, interlace))
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        line = bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:  # Sub
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif kind == 2:  # Up
            for i in range(stride):
                line[i] = (line[i] + previous[i]) & 255
        elif kind == 3:  # Average
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:  # Paeth
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b = previous[i]
                c = previous[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + predictor) & 255
        elif kind != 0:
            raise ValueError("bad PNG filter type %d in row %d" % (kind, y))
        rows.append(bytes(line))
        previous = line
    return width, height, channels, rows


def pixels(png):
    """The (r, g, b) of every pixel, row by row."""
    width, height, channels, rows = decode_png(png)
    out = []
    for line in rows:
        if channels >= 3:
            out.extend(zip(line[0::channels], line[1::channels], line[2::channels]))
        else:
            out.extend((v, v, v) for v in line[0::channels])
    return width, height, out


def is_magenta(p, slack=40):
    """The character's unlit #ff00ff, with a little slack for blending at its edges."""
    r, g, b = p
    return r >= 255 - slack and b >= 255 - slack and g <= slack


def picture_stats(png):
    width, height, px = pixels(png)
    counts = {}
    for p in px:
        counts[p] = counts.get(p, 0) + 1
    background, most = max(counts.items(), key=lambda kv: kv[1])
    return {
        "width": width, "height": height,
        "colours": len(counts),
        "background": background,
        "not_background": 1.0 - most / len(px),
        "magenta": sum(n for p, n in counts.items() if is_magenta(p)),
        "exact_magenta": counts.get((255, 0, 255), 0),
    }


# --- Chromium over the DevTools protocol (--remote-debugging-pipe: fd 3 in, fd 4 out) ---

class Browser:
    def __init__(self, binary, extra_flags, log_path):
        self.profile = tempfile.mkdtemp(prefix="sightline-replay-check-")
        to_child_r, self._to_child = os.pipe()
        self._from_child, from_child_w = os.pipe()

        def child_fds():
            # Copy both ends above 4 first, so neither is clobbered by the other's dup2; the
            # copies made by dup2 are inherited, every other descriptor is close-on-exec.
            a = fcntl.fcntl(to_child_r, fcntl.F_DUPFD, 10)
            b = fcntl.fcntl(from_child_w, fcntl.F_DUPFD, 10)
            os.dup2(a, 3)
            os.dup2(b, 4)

        flags = [
            "--headless=new", "--remote-debugging-pipe",
            # Software WebGL: ANGLE on SwiftShader (no GPU in CI), allowed explicitly.
            "--use-angle=swiftshader", "--use-gl=angle", "--enable-unsafe-swiftshader",
            "--ignore-gpu-blocklist",
            # A quiet, offline, throwaway browser.
            "--no-first-run", "--no-default-browser-check", "--disable-background-networking",
            "--disable-component-update", "--disable-sync", "--disable-quic",
            "--disable-extensions", "--hide-scrollbars", "--mute-audio",
            "--user-data-dir=" + self.profile,
            "--enable-logging=stderr", "--v=0",
        ] + extra_flags
        if os.geteuid() == 0:
            flags.append("--no-sandbox")  # Chromium refuses to run as root with its sandbox
        self.log = open(log_path, "wb")
        self.process = subprocess.Popen(
            [binary] + flags + ["about:blank"], stdin=subprocess.DEVNULL, stdout=self.log,
            stderr=self.log, preexec_fn=child_fds, close_fds=False)
        os.close(to_child_r)
        os.close(from_child_w)
        self._next_id = 0
        self._replies = {}
        self._events = queue.Queue()
        self._lock = threading.Condition()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        buffer = b""
        while True:
            chunk = os.read(self._from_child, 1 << 16)
            if not chunk:
                with self._lock:
                    self._closed = True
                    self._lock.notify_all()
                return
            buffer += chunk
            while b"\0" in buffer:
                message, buffer = buffer.split(b"\0", 1)
                data = json.loads(message)
                if "id" in data:
                    with self._lock:
                        self._replies[data["id"]] = data
                        self._lock.notify_all()
                else:
                    self._events.put(data)

    _closed = False

    def call(self, method, params=None, session=None, timeout=60):
        with self._lock:
            self._next_id += 1
            ident = self._next_id
        message = {"id": ident, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self._to_child, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + timeout
        with self._lock:
            while ident not in self._replies:
                if self._closed:
                    raise RuntimeError("the browser closed its DevTools pipe (see its log)")
                left = deadline - time.monotonic()
                if left <= 0:
                    raise RuntimeError("no reply to %s in %d s" % (method, timeout))
                self._lock.wait(left)
            reply = self._replies.pop(ident)
        if "error" in reply:
            raise RuntimeError("%s: %s" % (method, reply["error"].get("message")))
        return reply.get("result", {})

    def events(self):
        out = []
        while True:
            try:
                out.append(self._events.get_nowait())
            except queue.Empty:
                return out

    def close(self):
        try:
            self.call("Browser.close", timeout=10)
        except Exception:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
        self.log.close()
        subprocess.run(["rm", "-rf", self.profile], check=False)


def javascript_errors(events, session):
    """Console errors, assertion failures, uncaught exceptions and error log entries of one
    page, as lines of text."""
    errors = []
    for e in events:
        if e.get("sessionId") != session:
            continue
        method, p = e.get("method"), e.get("params", {})
        if method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
            text = " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", []))
            errors.append("console.%s: %s" % (p["type"], text))
        elif method == "Runtime.exceptionThrown":
            d = p.get("exceptionDetails", {})
            text = (d.get("exception", {}).get("description") or d.get("text", "")).split("\n")[0]
            errors.append("uncaught exception: %s (line %s)" % (text, d.get("lineNumber")))
        elif method == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
            entry = p["entry"]
            errors.append("log error (%s): %s %s" % (entry.get("source"), entry.get("text"),
                                                     entry.get("url", "")))
    return errors


STATE_SCRIPT = """JSON.stringify((function () {
  var root = document.documentElement, s = null;
  document.querySelectorAll('section.replay').forEach(function (x) {
    if (x.dataset.run) s = s || x;
    if (x.dataset.scene === %s && x.dataset.run) s = x;
  });
  var canvas = s && s.querySelector(%s), r = canvas && canvas.getBoundingClientRect();
  return {replay: root.dataset.replay || '', error: root.dataset.replayError || '',
          run: s && s.dataset.run, frame: s && s.dataset.frame, t: s && s.dataset.t,
          hidden: s && s.dataset.hidden, scene: s && s.dataset.scene,
          canvas: r ? [r.left, r.top, r.width, r.height] : null};
})())"""

# The canvas each panel shows: the orbit view, or the main camera of the selected run.
PANEL_CANVAS = {"world": "canvas.replay-world", "camera": "canvas.replay-camera[data-slot=a]"}


def shoot(browser, url, scene_id, panel, size, timeout):
    """Opens url in a fresh tab, waits for the replay to say ready (or error), and returns
    (png bytes of the panel's canvas, or of the window when there is none; state dict;
    javascript errors)."""
    width, height = size
    target = browser.call("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = browser.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
    try:
        for domain in ("Page", "Runtime", "Log"):
            browser.call(domain + ".enable", session=session)
        browser.call("Emulation.setDeviceMetricsOverride",
                     {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
                     session=session)
        browser.call("Page.navigate", {"url": url}, session=session)
        deadline = time.monotonic() + timeout
        state = {}
        while time.monotonic() < deadline:
            value = browser.call("Runtime.evaluate",
                                 {"expression": STATE_SCRIPT % (json.dumps(scene_id),
                                                                json.dumps(PANEL_CANVAS[panel])),
                                  "returnByValue": True}, session=session)
            state = json.loads(value.get("result", {}).get("value") or "{}")
            if state.get("replay") in ("ready", "error"):
                break
            time.sleep(0.2)
        params = {"format": "png"}
        if state.get("canvas"):
            x, y, w, h = state["canvas"]
            if w >= 1 and h >= 1:
                params["clip"] = {"x": x, "y": y, "width": w, "height": h, "scale": 1}
        shot = browser.call("Page.captureScreenshot", params, session=session, timeout=timeout)
        png = base64.b64decode(shot["data"])
        time.sleep(0.3)  # let late console events arrive
        return png, state, javascript_errors(browser.events(), session)
    finally:
        browser.call("Target.closeTarget", {"targetId": target})


# --- the page's own data: scenes, runs, frame times and the independent check's flags ---

def read_scene_data(page_path):
    """{scene id: data} for every replay section of the page, inline or in a .js beside it."""
    html = open(page_path, encoding="utf-8").read()

    def attributes(text):
        return dict((k, unescape(v1 or v2)) for k, v1, v2 in
                    re.findall(r"([\w-]+)=(?:'([^']*)'|\"([^\"]*)\")", text))

    scenes, current = {}, None
    # Scripts are matched whole, so a <section> written inside one (the replay's own
    # comments) is not taken for a section.
    for m in re.finditer(r"<script\b([^>]*)>(.*?)</script>|<section\b([^>]*)>", html, re.S):
        if m.group(3) is not None:
            attrs = attributes(m.group(3))
            if "replay" not in attrs.get("class", "").split():
                continue
            current = attrs.get("data-scene")
            if "data-src" in attrs:
                text = open(os.path.join(os.path.dirname(page_path), attrs["data-src"]),
                            encoding="utf-8").read()
                # (window.sightlineReplayData=...||{})["ID"]={...};
                d = re.search(r"\]\s*=\s*(\{.*\})\s*;?\s*$", text, re.S)
                if not d:
                    raise ValueError("%s: no scene data assignment" % attrs["data-src"])
                scenes[current] = json.loads(d.group(1))
                current = None
        elif current is not None and "replay-data" in attributes(m.group(1)).get("class", ""):
            scenes[current] = json.loads(m.group(2))
            current = None
    return scenes


def runs_of(data):
    """[(id, label, times, hidden flags)] of a scene's data."""
    runs = data["runs"]
    out = []
    for r in runs:
        track = r.get("track")
        if track is None:
            track = runs[r["track_of"]]["track"]
        t = struct.unpack("<%df" % (len(base64.b64decode(track)) // 4), base64.b64decode(track))
        times = list(t[0::5])
        flags = base64.b64decode(r["flags"])
        out.append((r["id"], r.get("label", ""), times, [bool(f & 2) for f in flags]))
    return out


def short_name(rid, label):
    """A run's solver label for file names: from 'solver / profile / seed 1', a suite id
    'scene__solver__profile__s1__hash', or a trace file name."""
    if "__" in rid:
        return rid.split("__")[1]
    name = label.split(" / ")[0] or rid
    for suffix in (".csv", ".trace"):
        if name.endswith(suffix):
            name = name[:-len(suffix)]
    return re.sub(r"[^\w.-]", "_", name)


def find_run(runs, name):
    for r in runs:
        rid, label = r[0], r[1]
        if name in (rid, label) or label.split(" / ")[0] == name or ("__%s__" % name) in rid:
            return r
    raise LookupError("no run %r among %s" % (name, [r[0] for r in runs]))


def stretches(flags, value):
    """Maximal runs [start, end) of frames whose flag is `value`, longest first."""
    out, start = [], None
    for i, f in enumerate(flags + [not value]):
        if f == value and start is None:
            start = i
        elif f != value and start is not None:
            out.append((start, i))
            start = None
    return sorted(out, key=lambda s: (s[0] - s[1], s[0]))


def frames_in(flags, value, count):
    """Up to `count` frames with flag == value, each in the middle of a different longest
    stretch (away from where visibility changes), then more spread over the longest one."""
    runs = stretches(flags, value)
    picked = [(a + b - 1) // 2 for a, b in runs[:count]]
    if runs and len(picked) < count:
        # Evenly over the longest stretch, away (half a second at 60 fps) from those picked.
        a, b = runs[0]
        for k in range(1, count + 1):
            f = a + (b - a) * k // (count + 1)
            if len(picked) < count and all(abs(f - p) >= 30 for p in picked):
                picked.append(f)
    return sorted(set(picked))


# --- the checks ---

def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("page", help="the replay page (report.html, view.html)")
    parser.add_argument("--name", required=True, help="prefix of the screenshots' names")
    parser.add_argument("--scene",
                        help="the scene to check: its id on the page, or a part of it "
                             "(default: the first scene of the page)")
    parser.add_argument("--run", action="append", default=[],
                        help="a run whose visible frames to check (id, label or solver label; "
                             "repeatable; default: every run of the scene)")
    parser.add_argument("--hidden-run", action="append", default=[],
                        help="a run that must show NO magenta at its hidden frames")
    parser.add_argument("--visible-frames", type=int, default=2)
    parser.add_argument("--out", required=True, help="folder for the screenshots")
    parser.add_argument("--browser", default="chromium")
    parser.add_argument("--size", default="800x600", help="window size WIDTHxHEIGHT")
    parser.add_argument("--timeout", type=float, default=60, help="seconds per page")
    parser.add_argument("--min-colours", type=int, default=64,
                        help="distinct colours the world view must show")
    parser.add_argument("--min-magenta", type=int, default=20,
                        help="magenta pixels that count as 'the character is on screen'")
    args = parser.parse_args()
    size = tuple(int(x) for x in args.size.split("x"))
    os.makedirs(args.out, exist_ok=True)

    page = os.path.abspath(args.page)
    scenes = read_scene_data(page)
    if args.scene is None:
        matching = list(scenes)[:1]
    else:
        matching = [s for s in scenes if s == args.scene] or [s for s in scenes if args.scene in s]
    if len(matching) != 1:
        print("check-replay: scene %r matches %s on %s (scenes: %s)"
              % (args.scene, matching or "nothing", args.page, list(scenes)), file=sys.stderr)
        return 2
    scene_id = matching[0]
    runs = runs_of(scenes[scene_id])
    try:
        visible_runs = [find_run(runs, n) for n in args.run] if args.run else runs
        hidden_runs = [find_run(runs, n) for n in args.hidden_run]
    except LookupError as e:
        print("check-replay: %s: %s" % (args.page, e), file=sys.stderr)
        return 2

    # (run, frame, panel, expect): expect "world", "magenta" or "no-magenta".
    plan = []
    for run in visible_runs:
        frames = frames_in(run[3], False, args.visible_frames)
        if not frames:
            print("check-replay: note: run %s has no frame with the look-at point visible"
                  % run[0])
        plan += [(run, f, "camera", "magenta") for f in frames]
    for run in hidden_runs:
        frames = frames_in(run[3], True, 1)
        if not frames:
            print("check-replay: run %s has no frame with the look-at point hidden" % run[0],
                  file=sys.stderr)
            return 1
        plan.append((run, frames[0], "camera", "no-magenta"))
    world_run = visible_runs[0] if visible_runs else runs[0]
    world_frames = frames_in(world_run[3], False, 1) or [0]
    plan.insert(0, (world_run, world_frames[0], "world", "world"))

    failures = []
    browser = Browser(args.browser, ["--window-size=%d,%d" % size],
                      os.path.join(args.out, args.name + "-chromium.log"))
    try:
        version = browser.call("Browser.getVersion")
        print("check-replay: %s, %s (scene %s)" % (version.get("product"), args.page, scene_id))
        for (rid, label, times, hidden), frame, panel, expect in plan:
            t = times[frame]
            fragment = "run=%s&t=%.4f&panel=%s" % (rid, t, panel)
            url = "file://" + page + "#" + fragment
            started = time.monotonic()
            png, state, errors = shoot(browser, url, scene_id, panel, size, args.timeout)
            shot = os.path.join(args.out, "%s-%s-f%d-%s.png"
                                % (args.name, short_name(rid, label), frame, panel))
            with open(shot, "wb") as f:
                f.write(png)
            stats = picture_stats(png)
            problems = list(errors)
            if state.get("replay") != "ready":
                problems.append("dataset.replay is %r (%s)" % (state.get("replay"),
                                                             state.get("error")))
            if state.get("run") != rid or state.get("frame") != str(frame):
                problems.append("the page drew run %s frame %s, not run %s frame %d"
                                % (state.get("run"), state.get("frame"), rid, frame))
            # The panel asked for fills the window (the fragment's &panel=).
            box = state.get("canvas")
            if not box or box[2] * box[3] < 0.9 * size[0] * size[1]:
                problems.append("the %s canvas does not fill the window: %s" % (panel, box))
            if state.get("hidden") not in (None, "1" if hidden[frame] else "0"):
                problems.append("the page says data-hidden=%s, its data says %d"
                                % (state.get("hidden"), hidden[frame]))
            if expect == "world":
                if stats["colours"] < args.min_colours or stats["not_background"] < 0.2:
                    problems.append("the 3D view looks blank: %d colours, %.0f%% of pixels "
                                    "not the background" % (stats["colours"],
                                                            100 * stats["not_background"]))
            elif expect == "magenta" and stats["magenta"] < args.min_magenta:
                problems.append("the look-at point is visible (independent check) but only %d "
                                "magenta pixels are on screen" % stats["magenta"])
            elif expect == "no-magenta" and stats["magenta"] > 0:
                problems.append("the look-at point is hidden (independent check) but %d "
                                "magenta pixels are on screen" % stats["magenta"])
            print("  %-5s %s t=%.3f frame %d (%s): %d colours, %.0f%% not background, %d "
                  "magenta px, %.1f s -> %s"
                  % ("FAIL" if problems else "ok", panel, t, frame,
                     "hidden" if hidden[frame] else "visible", stats["colours"],
                     100 * stats["not_background"], stats["magenta"],
                     time.monotonic() - started, shot))
            for p in problems:
                print("        " + p)
                failures.append("%s: %s: %s" % (args.name, fragment, p))
    except RuntimeError as e:
        print("check-replay: the browser failed: %s" % e, file=sys.stderr)
        return 2
    finally:
        browser.close()
    if failures:
        print("check-replay: %d problem(s) on %s" % (len(failures), args.page), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
