#!/usr/bin/env bash
# Regenerates the G-code samples in this folder with real Inkscape Gcodetools.
#
# Needs the Debian packages inkscape (1.2, ships Gcodetools 1.7), potrace, imagemagick,
# python3-lxml, python3-numpy and python3-cssselect (inkex imports it; Inkscape only
# "recommends" it). Gcodetools runs with the SYSTEM python3, never the project's venv.
#
# The workflow is the operator's one, step by step, as the Inkscape menus would run it:
#   1. a drawing on a layer (hand-made shapes, or a bitmap traced with potrace);
#   2. Path > Object to Path (inkscape --actions=...object-to-path);
#   3. Extensions > Gcodetools > Orientation points  (--active-tab=orientation);
#   4. Extensions > Gcodetools > Tools library       (--active-tab=tools_library);
#   5. editing the tool's fields with the Text tool   (set_tool below);
#   6. Extensions > Gcodetools > Path to Gcode        (--active-tab=path-to-gcode).
# The <name>.svg kept here is the drawing as step 6 read it (layer, orientation points,
# tool definition); <name>.ngc is what Gcodetools wrote.
#
# Usage: bash resources/samples/make_samples.sh      (rewrites *.svg, *.ngc, logo.png, traced_drawing.png here)
set -euo pipefail

HERE=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
GT=/usr/share/inkscape/extensions/other/gcodetools/gcodetools.py
PY=/usr/bin/python3
export PYTHONPATH=/usr/share/inkscape/extensions

# gcodetools.py with the defaults of its .inx files (what Inkscape passes from the dialog).
# Two defaults of the bare command line differ from the dialog and break it:
# --path-to-gcode-depth-function defaults to "zd" (NameError) and --postprocessor to ""
# (UnboundLocalError in export_gcode); the dialog sends "d" and " ".
gt() {
    "$PY" "$GT" --biarc-max-split-depth=4 --path-to-gcode-depth-function=d \
        --path-to-gcode-sort-paths=true --Zscale=1 --Zoffset=0 --auto_select_paths=true \
        --min-arc-radius=0.05 --comment-gcode= --comment-gcode-from-properties=false \
        --add-numeric-suffix-to-filename=false --postprocessor-custom= \
        --create-log=false "$@"
}

# Text tool step: set the value of fields of the layer's Gcodetools tool definition.
# usage: set_tool FILE key=value ...
set_tool() {
    "$PY" - "$@" <<'EOF'
import sys
from lxml import etree
path, pairs = sys.argv[1], dict(a.split("=", 1) for a in sys.argv[2:])
tree = etree.parse(path)
done = set()
for group in tree.iter("{*}g"):
    if group.get("gcodetools") != "Gcodetools tool parameter":
        continue
    texts = {t.get("gcodetools"): t for t in group.iter("{*}text")}
    key = "".join(texts["Gcodetools tool definition field name"].itertext())
    if key in pairs:
        value = texts["Gcodetools tool definition field value"]
        for tspan in value.iter("{*}tspan"):
            tspan.text = pairs[key]
        done.add(key)
missing = set(pairs) - done
if missing:
    sys.exit(f"set_tool: no field {sorted(missing)} in {path}")
tree.write(path, xml_declaration=True, encoding="UTF-8")
EOF
}

# Move the second orientation point (the operator drags it in Inkscape) to x = X user units.
# usage: move_orientation_point FILE X
move_orientation_point() {
    "$PY" - "$@" <<'EOF'
import sys
from lxml import etree
path, x = sys.argv[1], float(sys.argv[2])
tree = etree.parse(path)
points = [g for g in tree.iter("{*}g")
          if g.get("gcodetools") == "Gcodetools orientation point (2 points)"]
assert len(points) == 2, points
second = points[1]
x0 = float(second.find("{*}path").get("d").split()[1])
second.set("transform", f"translate({x - x0:g},0)")
tree.write(path, xml_declaration=True, encoding="UTF-8")
EOF
}

# Put potrace's group on the "Cut" layer of a 150 mm page, scaled to WIDTH mm wide at (X, Y).
# usage: on_layer TRACED.svg WIDTH X Y > DESIGN.svg
on_layer() {
    "$PY" - "$@" <<'EOF'
import sys
from lxml import etree
src = etree.parse(sys.argv[1]).getroot()
width = float(src.get("viewBox").split()[2])
scale = float(sys.argv[2]) / width
traced = src.find("{http://www.w3.org/2000/svg}g")
print('''<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
     width="150mm" height="150mm" viewBox="0 0 150 150" version="1.1">
  <sodipodi:namedview id="namedview1" inkscape:current-layer="layer1" inkscape:document-units="mm"/>
  <g inkscape:groupmode="layer" id="layer1" inkscape:label="Cut">''')
print(f'    <g id="traced" transform="translate({sys.argv[3]},{sys.argv[4]}) scale({scale:.6f})">')
for i, path in enumerate(traced.iter("{http://www.w3.org/2000/svg}path")):
    print(f'      <path id="trace{i}" transform="{traced.get("transform")}" d="{path.get("d")}" '
          'style="fill:#000000;stroke:none"/>')
print('    </g>\n  </g>\n</svg>')
EOF
}

# The drawing header: a 150 x 150 mm page (1 user unit = 1 mm), one layer "Cut".
page() {
    cat <<EOF
<?xml version="1.0" encoding="UTF-8"?>
<svg xmlns="http://www.w3.org/2000/svg"
     xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
     xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
     width="150mm" height="150mm" viewBox="0 0 150 150" version="1.1">
  <sodipodi:namedview id="namedview1" inkscape:current-layer="layer1" inkscape:document-units="mm"/>
  <g inkscape:groupmode="layer" id="layer1" inkscape:label="Cut">
EOF
}
STYLE='style="fill:none;stroke:#000000;stroke-width:0.5"'

# sample NAME UNIT ZSURFACE ZDEPTH ZSAFE ORDER BIARC_TOL TOOL_FIELDS...
# Runs steps 2-6 on $WORK/NAME.design.svg.
sample() {
    local name=$1 unit=$2 zsurface=$3 zdepth=$4 zsafe=$5 order=$6 tol=$7
    shift 7
    local unitarg
    if [ "$unit" = in ]; then unitarg="G20 (All units in inches)"; else unitarg="G21 (All units in mm)"; fi
    cd "$WORK"
    inkscape --actions="select-all:all;object-to-path" --export-type=svg \
        --export-filename="$name.paths.svg" "$name.design.svg" 2>/dev/null
    gt "--postprocessor= " --active-tab=orientation --orientation-points-count=2 --Zsurface="$zsurface" \
        --Zdepth="$zdepth" "--unit=$unitarg" "$name.paths.svg" > "$name.oriented.svg"
    if [ "$unit" = in ]; then
        # Gcodetools puts the inch points 5 user units apart: on this mm page that would be
        # 5 in per 5 mm. Drag the second point to 127 mm so 1 in = 25.4 mm.
        move_orientation_point "$name.oriented.svg" 127
    fi
    gt "--postprocessor= " --active-tab=tools_library "--tools-library-type=cylinder cutter" \
        "$name.oriented.svg" > "$name.svg"
    set_tool "$name.svg" "$@"
    # POST: the dialog's "Post-processor" choice (" " = None)
    gt --active-tab=path-to-gcode --biarc-tolerance="$tol" "--path-to-gcode-order=$order" \
        "--postprocessor=${POST:- }" \
        --Zsafe="$zsafe" "--unit=$unitarg" --directory="$WORK" --filename="$name.ngc" \
        "$name.svg" > "$name.preview.svg"
    cp "$name.svg" "$name.ngc" "$HERE/"
    echo "made $name.ngc: $(wc -l < "$name.ngc") lines"
}

# 1. arcs_circles: circles, an ellipse, partial arcs and SVG arc commands; one pass 0.5 mm deep.
{ page; cat <<EOF
    <circle id="circle_big" cx="40" cy="40" r="25" $STYLE/>
    <circle id="circle_small" cx="40" cy="40" r="6" $STYLE/>
    <ellipse id="ellipse" cx="108" cy="40" rx="30" ry="15" $STYLE/>
    <path id="arc_open" sodipodi:type="arc" sodipodi:cx="108" sodipodi:cy="40" sodipodi:rx="10"
          sodipodi:ry="10" sodipodi:start="0.5" sodipodi:end="5.2" sodipodi:open="true"
          sodipodi:arc-type="arc" d="" $STYLE/>
    <path id="waves" d="M 15,95 A 10,10 0 0 1 35,95 A 10,10 0 0 0 55,95 A 10,10 0 0 1 75,95
          A 10,10 0 0 0 95,95 A 10,10 0 0 1 115,95 A 10,10 0 0 0 135,95" $STYLE/>
    <path id="lens" d="M 40,130 A 30,30 0 0 1 110,130 A 45,45 0 0 1 40,130 Z" $STYLE/>
  </g>
</svg>
EOF
} > "$WORK/arcs_circles.design.svg"
sample arcs_circles mm 0 -0.5 5 "subpath by subpath" 0.05 \
    "feed=400" "penetration feed=100" "depth step=1" "diameter=3"

# 2. star_passes: a star, a rounded frame and a circle cut 3 mm deep in 0.75 mm steps
#    (four Z passes per path, "path by path").
{ page; cat <<EOF
    <rect id="frame" x="12" y="12" width="126" height="126" rx="12" $STYLE/>
    <path id="star" sodipodi:type="star" sodipodi:sides="5" sodipodi:cx="75" sodipodi:cy="70"
          sodipodi:r1="45" sodipodi:r2="18" sodipodi:arg1="-1.5708" sodipodi:arg2="-0.9425"
          inkscape:flatsided="false" inkscape:rounded="0" inkscape:randomized="0" d="" $STYLE/>
    <circle id="hole" cx="75" cy="70" r="8" $STYLE/>
  </g>
</svg>
EOF
} > "$WORK/star_passes.design.svg"
sample star_passes mm 0 -3 5 "path by path" 0.05 \
    "feed=300" "penetration feed=60" "depth step=0.75" "diameter=2"

# 3. inch_plate: a plate outline with four holes and the text "CNC 150" (text -> path), in
#    inches: 0.04 in deep in two 0.02 in passes, 16 in/min.
{ page; cat <<EOF
    <rect id="plate" x="10" y="35" width="130" height="80" rx="4" $STYLE/>
    <circle id="hole_1" cx="20" cy="45" r="3.175" $STYLE/>
    <circle id="hole_2" cx="130" cy="45" r="3.175" $STYLE/>
    <circle id="hole_3" cx="20" cy="105" r="3.175" $STYLE/>
    <circle id="hole_4" cx="130" cy="105" r="3.175" $STYLE/>
    <text id="label" x="75" y="85" style="font-family:'DejaVu Sans';font-weight:bold;font-size:22px;text-anchor:middle;fill:none;stroke:#000000;stroke-width:0.3">CNC 150</text>
  </g>
</svg>
EOF
} > "$WORK/inch_plate.design.svg"
sample inch_plate in 0 -0.04 0.2 "path by path" 0.002 \
    "feed=16" "penetration feed=4" "depth step=0.02" "diameter=0.0625"

# A bitmap $WORK/BITMAP.png traced by potrace, its paths put on the layer WIDTH mm wide at
# (X, Y), then cut by Gcodetools in one pass DEPTH deep (F350, plunge F80), kept as NAME.
# usage: traced BITMAP NAME WIDTH X Y DEPTH
traced() {
    local bitmap=$1 name=$2
    convert "$WORK/$bitmap.png" -threshold 50% "$WORK/$bitmap.pbm"
    potrace -s --alphamax 1.0 --opttolerance 0.2 -o "$WORK/$bitmap.traced.svg" "$WORK/$bitmap.pbm"
    on_layer "$WORK/$bitmap.traced.svg" "$3" "$4" "$5" > "$WORK/$name.design.svg"
    cp "$WORK/$bitmap.png" "$HERE/"
    sample "$name" mm 0 "$6" 5 "subpath by subpath" 0.05 \
        "feed=350" "penetration feed=80" "depth step=1" "diameter=1"
}

# 4. potrace_logo: the "picture -> G-code" workflow. ImageMagick draws a bitmap, potrace
#    traces it to an SVG, its paths go on a layer 120 mm wide; one pass 0.8 mm deep.
cd "$WORK"
convert -size 580x240 xc:white -fill black -font DejaVu-Sans-Bold -pointsize 150 \
    -annotate +20+185 'CNC' -fill none -stroke black -strokewidth 18 \
    -draw 'circle 490,120 490,40' -strokewidth 0 -fill black -draw 'polygon 490,75 530,145 450,145' \
    -define png:exclude-chunks=date,time -strip "$WORK/logo.png"
traced logo potrace_logo 120 15 40 -0.8

# 5. text_round4: the word "Mill" (DejaVu Serif Italic, text -> path) engraved 1 mm deep
#    in two 0.5 mm passes cut "pass by pass" (every path at one depth, then the next),
#    with the post-processor "Round all values to 4 digits" (round(4);): the rounded arc
#    ends are no longer exactly on their circles.
{ page; cat <<EOF
    <text id="word" x="75" y="90" style="font-family:'DejaVu Serif';font-style:italic;font-size:48px;text-anchor:middle;fill:none;stroke:#000000;stroke-width:0.3">Mill</text>
  </g>
</svg>
EOF
} > "$WORK/text_round4.design.svg"
POST="round(4);" sample text_round4 mm 0 -1 3 "pass by pass" 0.02 \
    "feed=250" "penetration feed=50" "depth step=0.5" "diameter=0.8"

# 6. traced_drawing: the "picture -> G-code" workflow on a big drawing (the real traced file
#    the load benchmark copies, bench/tracedfile.py). ImageMagick draws a 2400 x 2400 px
#    bitmap from a fixed recipe: text in three fonts (URW Z003 script, DejaVu Serif Bold
#    Italic, DejaVu Sans and Serif Italic), a spiral ribbon, rings, a disc, an ellipse,
#    and a field of blobs (seeded random noise, blurred, thresholded); potrace traces it,
#    its paths go on the layer 140 mm wide at (5, 5); one pass 0.6 mm deep.
cd "$WORK"
convert -size 2400x1260 xc:gray50 -seed 24 +noise Random -channel G -separate +channel \
    -blur 0x9 -normalize -threshold 53% -negate -gravity center -crop 2240x1100+0+0 +repage \
    "$WORK/blobs.png"
"$PY" - > "$WORK/spiral.txt" <<'EOF'
# A spiral ribbon 26 px wide, 3.5 turns, as one polygon (out along the outer edge, back along the inner).
import math
n, turns, w = 1200, 3.5, 26
out, back = [], []
for k in range(n + 1):
    t = k / n * turns * 2 * math.pi
    r = 40 + 70 * t / (2 * math.pi)
    c, s = math.cos(t), math.sin(t)
    out.append(f"{400 + (r + w / 2) * c:.1f},{880 + (r + w / 2) * s:.1f}")
    back.append(f"{400 + (r - w / 2) * c:.1f},{880 + (r - w / 2) * s:.1f}")
print("polygon " + " ".join(out + back[::-1]))
EOF
convert -size 2400x2400 xc:white \
    -fill black -font Z003-Medium-Italic -pointsize 330 -annotate +90+300 'Gcodetools' \
    -font DejaVu-Serif-Bold-Italic -pointsize 120 -annotate +1650+230 'picture' \
    -annotate +1650+380 'to G-code' \
    -font DejaVu-Sans -pointsize 44 \
    -annotate +80+480 'potrace traces the bitmap, Gcodetools fits biarcs: G02 G03 with I J, six decimals.' \
    -font DejaVu-Serif-Italic \
    -annotate +80+545 'One pass 0.6 mm deep along every outline: the drawing of the load benchmark.' \
    -draw "$(cat "$WORK/spiral.txt")" \
    -fill none -stroke black -strokewidth 36 -draw 'circle 1800,880 1800,640' \
    -strokewidth 20 -draw 'circle 1800,880 1800,760' \
    -strokewidth 0 -fill black -draw 'circle 1800,880 1800,830' -draw 'ellipse 1230,880 110,200 0,360' \
    "$WORK/blobs.png" -geometry +80+1230 -compose multiply -composite \
    -threshold 50% -type bilevel -define png:exclude-chunks=date,time -strip "$WORK/traced_drawing.png"
traced traced_drawing traced_drawing 140 5 5 -0.6
