#!/usr/bin/env bash
# Screenshot of the ParaView GUI with the plugin's filter applied (run under Xvfb):
#   paraview-gui-screenshot.sh PLUGIN DATA_DIR OUTPUT.png
# Starts paraview with Testing/Python/ParaViewGUI.py, waits until the scene is
# ready, fails if the script's checks of the Torsion colour map failed, grabs
# the whole screen, closes paraview, and checks the picture shows the curve
# coloured by torsion.
set -euo pipefail
plugin=$1 data=$2 output=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A fresh user profile without the welcome dialog.
mkdir -p "$work/config/ParaView"
printf '[General]\nGeneralSettings.ShowWelcomeDialog=0\n' > "$work/config/ParaView/ParaView5.11.0.ini"
export XDG_CONFIG_HOME="$work/config" XDG_RUNTIME_DIR="$work"
export SHAPESPLINES_PLUGIN=$plugin SHAPESPLINES_DATA=$data SHAPESPLINES_READY="$work/ready"
paraview -geometry 1280x1000+0+0 --script="$here/../Python/ParaViewGUI.py" > "$work/paraview.log" 2>&1 &
pid=$!
for _ in $(seq 1 120); do
  [ -f "$work/ready" ] && break
  kill -0 "$pid" 2>/dev/null || { cat "$work/paraview.log"; echo "paraview exited early"; exit 1; }
  sleep 1
done
[ -f "$work/ready" ] || { cat "$work/paraview.log"; kill "$pid"; echo "paraview never got ready"; exit 1; }
# The script's report: "ready" or "failed", then what it checked.
cat "$work/ready"
[ "$(head -n 1 "$work/ready")" = ready ] || { cat "$work/paraview.log"; kill "$pid"; exit 1; }
sleep 5 # let Qt paint the panels
/usr/bin/python3 - "$output" <<'PY'
import sys
from PIL import ImageGrab
shot = ImageGrab.grab(xdisplay=None)
shot.save(sys.argv[1])
# The render view left of the scalar bar: the curve's own colours.
pixels = list(shot.convert("RGB").crop((300, 190, 1080, 960)).getdata())
warm = sum(1 for r, g, b in pixels if r > 140 and r > g + 60 and r > b + 40)
cool = sum(1 for r, g, b in pixels if b > 140 and b > r + 40)
print("screenshot %s: %dx%d, %d warm and %d cool pixels" % (sys.argv[1], shot.width, shot.height, warm, cool))
# Both ends of the map show. Over [-m, m] most of the aorta's cubic is near
# the map's white middle (about 190 warm pixels); over the data's own range,
# centred on +49, the curve is pale blue (about 65 warm pixels).
if warm < 100 or cool < 100:
    sys.exit("the screenshot does not show a curve coloured on a diverging map")
PY
kill "$pid"
wait "$pid" 2>/dev/null || true
