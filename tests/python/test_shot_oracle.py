"""scripts/shot_oracle.py on a scene written here: ben stands right behind ann, seen from a
region a few centimetres wide straight in front of her, for the first second (t = 0 .. 1 s
at 10 frames a second: 11 frames in which no pose can see half of him), then steps 5 m
aside (the other 10 frames: a pose from that region frames and sees both; the tracking
camera's look takes a frame or two to turn to him, and those frames the oracle must find
possible)."""
import os
import subprocess
import sys

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "shot_oracle.py")

SCENE = """name: behind
frame_rate: 10
actors:
  - name: ann
    trajectory:
      - {t: 0, position: [0, 0, 0], yaw: 0}
      - {t: 2, position: [0, 0, 0], yaw: 0}
  - name: ben
    trajectory:
      - {t: 0, position: [0, 0, -3], yaw: 0}
      - {t: 1, position: [0, 0, -3], yaw: 0}
      - {t: 1.05, position: [5, 0, -3], yaw: 0}
      - {t: 2, position: [5, 0, -3], yaw: 0}
shot:
  fov: 60
  region: {min: [-0.05, 0.95, 3.95], max: [0.05, 1.05, 4.05]}
  properties:
    - {kind: framed, target: ann}
    - {kind: framed, target: ben}
    - {kind: visible, target: ann, range: [0.5, 1]}
    - {kind: visible, target: ben, range: [0.5, 1]}
"""


def run(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


def test_counts_the_frames_no_pose_can_hold(tmp_path):
    scene = tmp_path / "behind.yaml"
    scene.write_text(SCENE)
    out = run(str(scene), "--budget-ms", "20")
    assert out.returncode == 0, out.stderr
    cells = [c.strip() for c in out.stdout.strip().splitlines()[-1].strip("|").split("|")]
    frames, held, no_pose = int(cells[1]), int(cells[2].split()[0]), int(cells[3])
    assert frames == 21
    assert no_pose == 11      # t = 0 .. 1 s: ben hidden behind ann from everywhere in the region
    assert 5 <= held <= 10    # t = 1.1 .. 2 s: both framed and seen once the look has turned
    assert cells[4] == f"{100 * held / 10:.1f}"


def test_a_missing_scene_is_an_error_naming_it(tmp_path):
    out = run(str(tmp_path / "nowhere.yaml"))
    assert out.returncode != 0
    assert "nowhere.yaml" in out.stderr
