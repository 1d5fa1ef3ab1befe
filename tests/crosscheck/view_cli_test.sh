#!/usr/bin/env bash
# Command-line tests of `crosscheck view`, one case per ctest test:
#   view_cli_test.sh CASE CROSSCHECK SOURCE_DIR ARTIFACTS_DIR HAVE_WINDOW
# HAVE_WINDOW is 1 when crosscheck was built with SDL2. Cases:
#   no_display      DISPLAY, WAYLAND_DISPLAY and SDL_VIDEODRIVER unset, no Xvfb: one error line, exit 2
#   bad_script      a bad line, a missing script, a bad scene: one line naming the file (and line), exit 2,
#                   before any window (so with no display too)
#   walk_room       under Xvfb: a scripted walk through scenes/room.json; the saved scene's camera is
#                   the steps the keys say, a screenshot of every view is kept in ARTIFACTS/view/walk_room/,
#                   and `crosscheck compare` of the saved scenes prints the metrics the viewer printed
#   light_and_time  under Xvfb: the light keys and time on a lit, spinning look-at scene
#   saved_difference under Xvfb: a view where the renderers differ (the fmuladd rounding lavapipe
#                   does not use, on the depth_slope fixture) is saved and compare prints the same
#                   non-zero metrics
# Exit 0: passed, 1: failed (with a message), 77: skipped (xvfb-run, python3 or SDL2 missing).
# Never checks a timing: the machine is shared.
set -uo pipefail
have_window=${5:-1}
source "$(dirname "${BASH_SOURCE[0]}")/cli_case.sh"
cli_case_begin view "$@"

# run COMMAND ARGS...: any command (crosscheck or a helper), not crosscheck's arguments alone.
run() {
  "$@" >"$artifacts/out.txt" 2>"$artifacts/err.txt"
  status=$?
}
# No display at all: no X, no Wayland, SDL left to pick its own driver.
headless() { env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER "$@"; }
need_window() {
  [ "$have_window" = 1 ] || { echo "SKIPPED: crosscheck was built without SDL2 (libsdl2-dev)"; exit 77; }
  command -v xvfb-run >/dev/null || { echo "SKIPPED: xvfb-run is not installed (Debian's xvfb)"; exit 77; }
  command -v python3 >/dev/null || { echo "SKIPPED: python3 is not installed"; exit 77; }
}
# Runs crosscheck view under a fresh Xvfb with a screen big enough for the window.
under_xvfb() { xvfb-run -a -s "-screen 0 1600x1200x24" "$@"; }

# The metrics `crosscheck compare SCENE [ARGS]` prints, spelled as the viewer's saved line spells them.
compare_metrics() {
  "$crosscheck" compare "$@" >"$artifacts/compare.txt" 2>&1
  local s=$?
  [ "$s" -le 1 ] || { cat "$artifacts/compare.txt"; fail "compare $* exit status $s"; }
  python3 - "$artifacts/compare.txt" <<'PY'
import re, sys
t = open(sys.argv[1], encoding="utf-8").read()
cov = re.search(r"coverage mismatches +(\d+)", t).group(1)
col = re.search(r"colour max \|Δ\| RGBA +(\d+ \d+ \d+ \d+)", t).group(1)
dep = re.search(r"depth max \|Δ\| +(\S+)", t).group(1)
print(f"coverage mismatches {cov}, colour max |Δ| RGBA {col}, depth max |Δ| {dep}")
PY
}
# The metrics of the viewer's "saved FILE: softraster METHOD, METRICS; --set ..." line for FILE.
saved_metrics() {
  grep -F "saved $1: " "$artifacts/out.txt" | sed -E 's/^saved [^:]+: softraster [^,]+, //; s/; --set .*$//'
}

case $case_name in
  no_display)
    run headless "$crosscheck" view scenes/room.json -o "$artifacts/out"
    expect_status 2
    if [ "$have_window" = 1 ]; then
      expect_err '^crosscheck: view: cannot open a window: SDL_Init: .+ \(DISPLAY is not set: run it on a desktop, or under xvfb-run -a\)$'
    else
      expect_err '^crosscheck: view: this crosscheck was built without SDL2'
    fi
    expect_one_error_line
    # With a script too, and nothing was written.
    printf 'frame\nsave x\n' >"$artifacts/ok.txt"
    run headless "$crosscheck" view scenes/room.json --script "$artifacts/ok.txt" -o "$artifacts/out"
    expect_status 2
    expect_err '^crosscheck: view: '
    expect_one_error_line
    [ ! -e "$artifacts/out" ] || fail "a run without a window wrote $artifacts/out"
    ;;
  bad_script)
    printf '# walk\nkey Up 3\njump 2\n' >"$artifacts/bad.txt"
    run headless "$crosscheck" view scenes/room.json --script "$artifacts/bad.txt"
    expect_status 2
    expect_err "^crosscheck: $artifacts/bad.txt:3: unknown command 'jump' \(expected key, frame, view, method, screenshot, save or quit\)$"
    expect_one_error_line
    printf 'key Up 0\n' >"$artifacts/zero.txt"
    run headless "$crosscheck" view scenes/room.json --script "$artifacts/zero.txt"
    expect_status 2
    expect_err "^crosscheck: $artifacts/zero.txt:1: '0': expected a whole number of frames from 1 to 100000$"
    expect_one_error_line
    run headless "$crosscheck" view scenes/room.json --script "$artifacts/missing.txt"
    expect_status 2
    expect_err "^crosscheck: $artifacts/missing.txt: cannot read script: file not found$"
    expect_one_error_line
    run headless "$crosscheck" view scenes/room.json --script scenes
    expect_status 2
    expect_err "^crosscheck: scenes: cannot read script: "
    expect_one_error_line
    run headless "$crosscheck" view tests/data/nope.json
    expect_status 2
    expect_err '^crosscheck: tests/data/nope.json: cannot open scene file: file not found$'
    expect_one_error_line
    run headless "$crosscheck" view scenes/room.json --method fast
    expect_status 2
    expect_err '^crosscheck: --method fast: expected one of exact, exact-scalar'
    expect_one_error_line
    run headless "$crosscheck" view scenes/room.json --set camera.yaw
    expect_status 2
    expect_err 'camera.yaw: expected KEY.PATH=VALUE$'
    expect_one_error_line
    ;;
  walk_room)
    need_window
    cat >"$artifacts/walk.txt" <<'EOF'
# A walk through the room: forward, a turn right, a look up; the room is unlit, so W moves nothing.
screenshot start
key Up 10
key Right 5
key PageUp 3
key W 3
save walk
view side
screenshot view-side
view soft
screenshot view-soft
view vulkan
screenshot view-vulkan
view diff
screenshot view-diff
view flicker
screenshot view-flicker-a
frame 8
screenshot view-flicker-b
view depth
screenshot view-depth
view depth-diff
screenshot view-depth-diff
view side
method exact-scalar
screenshot method-exact-scalar
save walk-scalar
key H
screenshot help
quit
key Up 50
EOF
    run under_xvfb "$crosscheck" view scenes/room.json --threads 2 --script "$artifacts/walk.txt" -o "$artifacts"
    expect_status 0
    grep -q "^saved $artifacts/walk.json: softraster exact, " "$artifacts/out.txt" || fail "no saved line for walk.json"
    grep -q "^saved $artifacts/walk-scalar.json: softraster exact-scalar, " "$artifacts/out.txt" ||
      fail "no saved line for walk-scalar.json"
    [ "$(grep -c '^screenshot ' "$artifacts/out.txt")" -eq 11 ] || fail "expected 11 screenshot lines"
    python3 - "$artifacts" <<'PY' || fail "the saved scene or the screenshots are not what the keys say"
import json, math, struct, sys, hashlib
out = sys.argv[1]
scene = json.load(open(f"{out}/walk.json"))
cam = scene["camera"]
# room.json: position [0, -0.45, -0.98], pitch -20, yaw 0. Up x10 moves 0.02 along the view
# direction (yaw 0, pitch -20: (0, sin 20, cos 20), y down), then Right x5 turns 2 degrees each and
# PageUp x3 pitches up 2 degrees each.
p = math.radians(-20)
forward = (0.0, -math.sin(p), math.cos(p))
pos = [0.0, -0.45, -0.98]
for _ in range(10):
    pos = [pos[i] + 0.02 * forward[i] for i in range(3)]
assert cam["yaw"] == 10, cam
assert cam["pitch"] == -14, cam
assert all(abs(a - b) < 1e-12 for a, b in zip(cam["position"], pos)), (cam["position"], pos)
assert cam["focal_length"] == 120 and cam["near"] == 0.05 and cam["far"] == 10, cam
# Only what changed: no light (the room is unlit) and no time; the mesh found from the new folder.
assert "light" not in scene and "time" not in scene, scene.keys()
assert scene["draws"][0]["obj"].endswith("scenes/meshes/cornell_box.obj"), scene["draws"][0]
assert "Saved by crosscheck view from room.json with --set camera.position=" in scene["description"]
assert json.load(open(f"{out}/walk-scalar.json"))["camera"] == cam

def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", path
    return struct.unpack(">II", head[16:24])

# The window: two 320x240 panes at 2x (1280 x 480) and the status band under them (6 lines of 24 + 10).
names = ["start", "view-side", "view-soft", "view-vulkan", "view-diff", "view-flicker-a", "view-flicker-b",
         "view-depth", "view-depth-diff", "method-exact-scalar", "help"]
digests = {}
for n in names:
    assert png_size(f"{out}/{n}.png") == (1280, 634), (n, png_size(f"{out}/{n}.png"))
    digests[n] = hashlib.sha256(open(f"{out}/{n}.png", "rb").read()).hexdigest()
for a, b in [("start", "view-side"), ("view-side", "view-soft"), ("view-soft", "view-diff"),
             ("view-flicker-a", "view-flicker-b"), ("view-depth", "view-side"), ("view-depth-diff", "view-diff"),
             ("help", "method-exact-scalar")]:
    assert digests[a] != digests[b], f"{a} and {b} look the same"
for n in ["walk.soft.png", "walk.vulkan.png", "walk.diff.png"]:
    assert png_size(f"{out}/{n}") == (320, 240), n
PY
    # The walk changed the picture: the saved view is not the room's own.
    "$crosscheck" render scenes/room.json --renderer soft -o "$artifacts/room.soft.png" >/dev/null 2>&1 || fail "render room"
    cmp -s "$artifacts/room.soft.png" "$artifacts/walk.soft.png" && fail "walk.soft.png is the room's own view"
    # crosscheck compare reproduces what the viewer printed, for each method it was saved with.
    expected=$(saved_metrics "$artifacts/walk.json")
    [ -n "$expected" ] || fail "no metrics on the saved line"
    got=$(compare_metrics "$artifacts/walk.json") || fail "compare walk.json"
    [ "$got" = "$expected" ] || fail "compare printed '$got', the viewer '$expected'"
    expected=$(saved_metrics "$artifacts/walk-scalar.json")
    got=$(compare_metrics "$artifacts/walk-scalar.json" --method exact-scalar) || fail "compare walk-scalar.json"
    [ "$got" = "$expected" ] || fail "compare printed '$got', the viewer '$expected'"
    echo "screenshots in $artifacts"
    ;;
  light_and_time)
    need_window
    # blinn_phong_obj: lit, spinning, a look-at camera, time 1.5. Space plays from its own frame on
    # (1 + 9 frames), the second Space pauses before its frame's step; then the light and a turn.
    cat >"$artifacts/lit.txt" <<'EOF'
key Space
frame 9
key Space
key W 3
key D 2
key E
key Left 4
save lit
screenshot lit
EOF
    run under_xvfb "$crosscheck" view scenes/blinn_phong_obj.json --threads 1 --script "$artifacts/lit.txt" -o "$artifacts"
    expect_status 0
    python3 - "$artifacts" "$src/scenes/blinn_phong_obj.json" <<'PY' || fail "the saved light, time or camera is not what the keys say"
import json, math, sys
out, original_path = sys.argv[1], sys.argv[2]
saved, original = json.load(open(f"{out}/lit.json")), json.load(open(original_path))
t = original.get("time", 0)
for _ in range(10):
    t += 1 / 30
assert saved["time"] == t, (saved["time"], t)
light = list(original.get("light", {}).get("position", [0, -0.5, -0.7]))
for _ in range(3):
    light[2] += 0.02
for _ in range(2):
    light[0] += 0.02
light[1] += 0.02
assert saved["light"]["position"] == light, (saved["light"], light)
for k, v in original["light"].items():
    if k != "position":
        assert saved["light"][k] == v
eye, target = original["camera"]["eye"], original["camera"]["target"]
assert saved["camera"]["eye"] == eye
# Left x4 swings the target 8 degrees about up around the eye: the distance stays.
d0 = math.dist(eye, target)
d1 = math.dist(eye, saved["camera"]["target"])
assert abs(d0 - d1) < 1e-12 and saved["camera"]["target"] != target, (d0, d1)
# The angle between the two view directions across up (both projected onto the plane normal to up).
up = original["camera"].get("up", [0, -1, 0])
n = math.sqrt(sum(u * u for u in up))
up = [u / n for u in up]
def across(p):
    v = [a - e for a, e in zip(p, eye)]
    along = sum(a * u for a, u in zip(v, up))
    return [a - along * u for a, u in zip(v, up)]
a, b = across(target), across(saved["camera"]["target"])
cos = sum(x * y for x, y in zip(a, b)) / (math.sqrt(sum(x * x for x in a)) * math.sqrt(sum(y * y for y in b)))
assert abs(math.degrees(math.acos(min(1, cos))) - 8) < 1e-9, math.degrees(math.acos(cos))
PY
    expected=$(saved_metrics "$artifacts/lit.json")
    got=$(compare_metrics "$artifacts/lit.json") || fail "compare lit.json"
    [ "$got" = "$expected" ] || fail "compare printed '$got', the viewer '$expected'"
    ;;
  saved_difference)
    need_window
    case "$(uname -m)" in
      x86_64 | i?86) if grep -qw fma /proc/cpuinfo; then other_fma=separate; else other_fma=fused; fi ;;
      aarch64 | arm64) other_fma=separate ;;
      *) other_fma=fused ;;
    esac
    printf 'key Up 3\nsave moved\n' >"$artifacts/moved.txt"
    run under_xvfb "$crosscheck" view tests/data/conformance/depth_slope.json --softraster-fma "$other_fma" \
      --script "$artifacts/moved.txt" -o "$artifacts"
    expect_status 0
    expected=$(saved_metrics "$artifacts/moved.json")
    case $expected in
      *"depth max |Δ| 0") fail "the renderers agree here ('$expected'): nothing different to reproduce" ;;
    esac
    got=$(compare_metrics "$artifacts/moved.json" --softraster-fma "$other_fma") || fail "compare moved.json"
    [ "$got" = "$expected" ] || fail "compare printed '$got', the viewer '$expected'"
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
echo "view cli $case_name: passed"
