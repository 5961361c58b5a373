"""The shapesplines command, as a user drives it from a shell: fit and audit on
.vtp, legacy .vtk and .csv files, the per-line summary, the documented options,
and every error path (exit status and a clear message, input never touched).

Run with Debian's python3 (NumPy): TestCommandLine.py --exe shapesplines --data Data --temp DIR
"""
import argparse
import hashlib
import math
import os
import re
import subprocess
import sys

import numpy as np

parser = argparse.ArgumentParser()
parser.add_argument("--exe", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--temp", required=True)
args = parser.parse_args()
os.makedirs(args.temp, exist_ok=True)

failures = []


def check(ok, what, detail=""):
    print(("ok   " if ok else "FAIL ") + what + (": " + detail if detail else ""))
    if not ok:
        failures.append(what)


def run(*words):
    result = subprocess.run([args.exe] + [str(w) for w in words], capture_output=True, text=True,
                            timeout=120)
    return result.returncode, result.stdout, result.stderr


def run_with_input(data, *words):
    """run() with data (bytes) on stdin."""
    result = subprocess.run([args.exe] + [str(w) for w in words], input=data, capture_output=True, timeout=120)
    return result.returncode, result.stdout.decode(), result.stderr.decode()


def temp(name):
    return os.path.join(args.temp, "cli-" + name)


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    values = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return {name: values[:, i] for i, name in enumerate(header)}


def write_csv(path, lines, header=True, line_ids=True):
    with open(path, "w") as f:
        if header:
            f.write("x,y,z,line_id\n" if line_ids else "x,y,z\n")
        f.write("# a comment line\n")
        for k, points in enumerate(lines):
            for p in points:
                f.write(",".join(repr(float(c)) for c in p) + ("," + str(k + 7) if line_ids else "") + "\n")


def write_legacy_vtk(path, lines):
    points = [p for line in lines for p in line]
    with open(path, "w") as f:
        f.write("# vtk DataFile Version 3.0\nlines\nASCII\nDATASET POLYDATA\n")
        f.write("POINTS %d double\n" % len(points))
        for p in points:
            f.write("%r %r %r\n" % tuple(float(c) for c in p))
        f.write("LINES %d %d\n" % (len(lines), sum(len(l) + 1 for l in lines)))
        start = 0
        for line in lines:
            f.write(" ".join(str(i) for i in [len(line)] + list(range(start, start + len(line)))) + "\n")
            start += len(line)


def helix(per_turn, turns, a=2.0, b=1.0):
    t = 2 * math.pi * np.arange(per_turn * turns + 1) / per_turn
    return np.column_stack([a * np.cos(t), a * np.sin(t), b * t])


# ---------------------------------------------------------------------------- help
code, out, err = run("--help")
options = ["--family", "--end-condition", "--kind", "--tension", "--max-tension", "--fixed", "--continuity",
           "--mode", "--knots", "--gamma", "--lambda", "--parameterization", "--closed", "--samples", "--arc-length",
           "--vmtk-names", "--data-tolerance", "--curve-tolerance", "--output", "--quiet", "--help", "--version",
           "--line-column"]
missing = [o for o in options if o not in out]
check(code == 0 and "fit INPUT" in out and "audit INPUT" in out and not missing,
      "--help documents both commands and every option", "missing %s" % missing if missing else "")
code2, out2, _ = run("fit", "--help")
check(code2 == 0 and out2 == out, "fit --help prints the same help")

# ---------------------------------------------------------------------------- fit: closed forms
helix_csv = temp("helix.csv")
write_csv(helix_csv, [helix(32, 3)], header=False, line_ids=False)
code, out, err = run("fit", helix_csv, "-o", temp("helix-out.csv"), "--samples", 4)
result = read_csv(temp("helix-out.csv"))
n = len(result["x"])
middle = slice(n // 4, 3 * n // 4)
k_err = np.max(np.abs(result["Curvature"][middle] - 0.4)) / 0.4
t_err = np.max(np.abs(result["Torsion"][middle] - 0.2)) / 0.2
# The cubic's errors at 32 points per turn are 0.32% and 0.64% (second order).
check(code == 0 and n == 96 * 4 + 1 and k_err < 5e-3 and t_err < 1e-2,
      "fit helix.csv (32 points per turn): curvature 0.4 and torsion 0.2 in the middle",
      "%d samples, relative errors %.1e and %.1e" % (n, k_err, t_err))
summary = [l for l in out.splitlines() if l.startswith("line ")]
check(len(summary) == 1 and "%d samples" % n in summary[0] and "shape violations 0" in summary[0],
      "the summary gives each line's samples and violations", summary[0] if summary else out)
length = float(summary[0].split("length ")[1].split(",")[0]) if summary else float("nan")
true_length = math.sqrt(5.0) * 6 * math.pi
check(abs(length - true_length) < 1e-4 * true_length, "the summary's length is the helix length",
      "%.6f vs %.6f" % (length, true_length))
check(np.allclose(result["line_id"], 0) and "Tangent_2" in result and "SpanIndex" in result,
      "CSV output: line_id, x, y, z and every point array by component")

# ---------------------------------------------------------------------------- readers agree
lines = [helix(8, 2), np.array([[0, 0, 0], [1, 0, 0], [2, 1, 0], [3, 3, 0.5], [4, 3, 1]], float)]
write_csv(temp("two.csv"), lines)
write_legacy_vtk(temp("two.vtk"), lines)
outputs = {}
for ext in ("csv", "vtk"):
    code, out, err = run("fit", temp("two." + ext), "-o", temp("two-%s.csv" % ext), "-q")
    outputs[ext] = read_csv(temp("two-%s.csv" % ext))
    check(code == 0 and out == "" and err == "", "fit two.%s -q: silent and successful" % ext, err)
same = all(np.array_equal(outputs["csv"][k], outputs["vtk"][k]) for k in outputs["csv"] if k != "line_id")
# The CSV's line ids (7, 8) are kept; the .vtk's lines have none: their places.
check(same and list(np.unique(outputs["csv"]["line_id"])) == [7, 8]
      and list(np.unique(outputs["vtk"]["line_id"])) == [0, 1],
      "CSV with line_id and legacy .vtk give the same two curves, each with its line ids")

code, out, err = run("fit", os.path.join(args.data, "aorta-centerline.vtp"), "-o", temp("aorta.vtp"),
                     "--family", "cubic", "--end-condition", "natural", "--arc-length", "0.5",
                     "--parameterization", "centripetal", "--vmtk-names")
check(code == 0 and os.path.getsize(temp("aorta.vtp")) > 0 and out.count("\nline ") + out.startswith("line ") == 2,
      "fit aorta.vtp -> .vtp with family options, arc-length sampling and VMTK names", out.strip()[-60:])
with open(temp("aorta.vtp"), "rb") as written:
    head = written.read()
check(b'compressor="vtkLZ4DataCompressor"' in head and b'<AppendedData encoding="raw">' in head,
      "a .vtp is written as raw appended data compressed by LZ4 (the fast writer setting)",
      head[:200].decode("latin-1"))

code, out, err = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-gencubic.csv"),
                     "--family", "gencubic", "--kind", "exponential", "--max-tension", "500")
code2, out2, _ = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-cubic.csv"))
gencubic = read_csv(temp("akima-gencubic.csv"))
check(code == 0 and "shape violations 0" in out and "shape violations 0" not in out2
      and gencubic["Tension"].max() > 0 and gencubic["Tension"].max() <= 500,
      "--family gencubic keeps Akima's shape where the cubic does not; Tension written",
      "%s | %s" % (out.strip().splitlines()[0], out2.strip().splitlines()[0]))

code, out, err = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-quintic.csv"),
                     "--family", "quintic", "--continuity", "c4")
code2, out2, _ = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-quintic-fixed.csv"),
                     "--family", "quintic", "--continuity", "c4", "--fixed")
quintic = read_csv(temp("akima-quintic.csv"))


def violations(text):
    return int(re.search(r"shape violations (\d+)", text).group(1))


# Fewer violations than at gamma = 1, and no cusp (the curvature within 1e4
# times Akima's largest discrete curvature, 0.29).
check(code == 0 and code2 == 0 and violations(out) < violations(out2) and 0 < quintic["Gamma"].min() <= 1
      and quintic["Curvature"].max() < 1e4 * 0.29,
      "--family quintic lowers Akima's violations without a cusp; Gamma written",
      "%s | %s" % (out.strip().splitlines()[0] if out.strip() else err, out2.strip().splitlines()[0]))

code, out, err = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-vdps.csv"),
                     "--family", "vdps")
code2, out2, err2 = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-vdps5.csv"),
                        "--family", "vdps", "--fixed")
vdps = read_csv(temp("akima-vdps.csv"))
check(code == 0 and code2 == 0 and "shape violations 0" in out and "shape violations 0" not in out2
      and vdps["Degree"].min() >= 5 and vdps["Degree"].max() > 5,
      "--family vdps keeps Akima's shape where degree 5 (the quintic) does not; Degree written",
      "%s | %s" % (out.strip().splitlines()[0] if out.strip() else err,
                   out2.strip().splitlines()[0] if out2.strip() else err2))
code, out, err = run("fit", os.path.join(args.data, "helix.vtp"), "-o", temp("helix-vdps.vtp"),
                     "--family", "vdps", "--mode", "approximate-global", "--knots", "6")
check(code == 0 and "shape violations 0" in out, "--family vdps --mode approximate-global",
      out.strip().splitlines()[0] if out.strip() else err)

code, out, err = run("fit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-qqr.csv"),
                     "--family", "qqr", "--fixed", "--z", "0.4")
qqr = read_csv(temp("akima-qqr.csv"))
check(code == 0 and "shape violations" in out and qqr["Alpha"].max() == 4,
      "--family qqr: local interpolation, Alpha written", out.strip().splitlines()[0] if out.strip() else err)

code, out, err = run("fit", os.path.join(args.data, "helix.vtp"), "-o", temp("helix-qqr.csv"),
                     "--family", "qqr", "--fixed")
code2, out2, err2 = run("fit", os.path.join(args.data, "helix.vtp"), "-o", temp("helix-qqr-local.csv"),
                        "--family", "qqr", "--fixed", "--mode", "local")
solved, local = read_csv(temp("helix-qqr.csv")), read_csv(temp("helix-qqr-local.csv"))
atPoints = local["Curvature"][::10] if code2 == 0 else None  # 10 samples a span: the points
check(code == 0 and code2 == 0 and abs(np.median(solved["Curvature"]) - 0.4) < 0.02
      and np.median(atPoints) > 2.5 * 0.4,
      "--family qqr interpolates (helix curvature 0.4); --mode local is the paper's, about 3x at the points",
      "median curvature %.4g, local at the points %.4g" % (np.median(solved["Curvature"]), np.median(atPoints))
      if code == 0 and code2 == 0 else err + err2)

code, out, err = run("fit", os.path.join(args.data, "helix.vtp"), "-o", temp("helix-gencubic.csv"),
                     "--family", "gencubic")
code2, out2, err2 = run("fit", os.path.join(args.data, "helix.vtp"), "-o", temp("helix-gencubic-natural.csv"),
                        "--family", "gencubic", "--end-condition", "natural")
ends, natural = read_csv(temp("helix-gencubic.csv")), read_csv(temp("helix-gencubic-natural.csv"))
check(code == 0 and code2 == 0 and abs(ends["Curvature"][0] - 0.4) < 0.1 and natural["Curvature"][0] < 0.01,
      "--family gencubic: polynomial ends by default (end curvature near the helix's 0.4), "
      "--end-condition natural gives 0 there",
      "end curvature %.4g and %.4g" % (ends["Curvature"][0], natural["Curvature"][0])
      if code == 0 and code2 == 0 else err + err2)

# ---------------------------------------------------------------------------- audit
code, out, err = run("audit", temp("two.csv"), temp("two-csv.csv"))
rows = [l for l in out.splitlines() if l.startswith("line ")]
check(code == 0 and len(rows) == 2 and all("shape violations" in r for r in rows),
      "audit INPUT CURVE: discrete shape and the curve's violations per line", rows[0] if rows else err)
code, out, err = run("audit", os.path.join(args.data, "akima.vtp"), "-o", temp("akima-shape.vtp"))
check(code == 0 and "collinear points" in out and os.path.isfile(temp("akima-shape.vtp")),
      "audit INPUT -o OUTPUT: the discrete shape written", out.strip())

# ---------------------------------------------------------------------------- errors
before = digest(temp("two.csv"))
cases = [
    (("fit", temp("two.csv"), "-o", temp("two.csv")), 1, "refusing to overwrite"),
    (("fit", temp("nothere.csv"), "-o", temp("x.vtp")), 1, "no such file"),
    (("fit", temp("two.csv"), "-o", temp("x.txt")), 1, "use .vtp or .csv"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--tension", "3"), 1, "unknown option --tension"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--samples", "0"), 1, "--samples must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--samples", "2.5"), 1, "--samples must be a whole number"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "vdps", "--mode", "approximate", "--knots", "4.5"), 1,
     "--knots must be a whole number"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--samples", "3", "--arc-length", "1"), 1, "not both"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "bezier"), 1, "unknown --family"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--end-condition", "free"), 1, "--end-condition must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "gencubic", "--kind", "spline"), 1, "--kind must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "gencubic", "--tension", "-1"), 1, "--tension must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--kind", "exponential"), 1, "unknown option --kind for this"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "quintic", "--continuity", "c5"), 1,
     "--continuity must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "quintic", "--gamma", "3"), 1, "--gamma must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "vdps", "--mode", "smooth"), 1, "--mode must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "vdps", "--degree", "4"), 1, "--degree must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "vdps", "--end-condition", "not-a-knot"), 1,
     "--end-condition must be polynomial, natural or clamped for vdps"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "gencubic", "--end-condition", "clamped"), 1,
     "--end-condition must be polynomial or natural for gencubic"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "qqr", "--alpha", "1"), 1, "--alpha must be"),
    (("fit", temp("two.csv"), "-o", temp("x.vtp"), "--family", "qqr", "--z", "2"), 1, "--z must be"),
    (("fit", temp("two.csv")), 1, "needs -o"),
    (("fit", temp("two.csv"), "-o"), 1, "needs a value"),
    (("audit",), 1, "audit takes INPUT"),
    (("frobnicate",), 1, "unknown command"),
    ((), 1, "no command"),
]
for words, expected, message in cases:
    code, out, err = run(*words)
    check(code == expected and message in err, "error: shapesplines %s" % " ".join(os.path.basename(str(w)) for w in words),
          "exit %d, %r" % (code, err.strip().splitlines()[0] if err.strip() else ""))
check(digest(temp("two.csv")) == before, "the input is never modified")

with open(temp("bad.csv"), "w") as f:
    f.write("0,0,0\n1,zero,0\n")
code, out, err = run("fit", temp("bad.csv"), "-o", temp("bad.vtp"))
check(code == 1 and "bad.csv:2:" in err, "a malformed CSV row is named by its line number", err.strip())

# A NaN in one line: that line is skipped with an error naming it, the other is written.
with open(temp("nan.csv"), "w") as f:
    f.write("0,0,0,0\n1,nan,0,0\n2,1,0,0\n3,3,0,0\n0,0,1,1\n1,1,1,1\n2,2,3,1\n")
code, out, err = run("fit", temp("nan.csv"), "-o", temp("nan-out.csv"))
nan_out = read_csv(temp("nan-out.csv"))
check(code == 2 and "cell 0" in err and "not finite" in err and len(nan_out["x"]) == 21
      and np.all(np.isfinite(nan_out["Curvature"])),
      "a NaN line is skipped with an error naming the cell (exit 2); the other line is written",
      "exit %d, %r, %d rows" % (code, err.strip(), len(nan_out["x"])))

# A damaged file (a cell refers to a point it does not have): that line is
# skipped with an error naming it, never a crash; the other line is used.
with open(temp("damaged.vtk"), "w") as f:
    f.write("# vtk DataFile Version 3.0\ndamaged ids\nASCII\nDATASET POLYDATA\nPOINTS 10 double\n")
    for k in range(10):
        f.write("%g %g %g\n" % (math.cos(0.6 * k), math.sin(0.6 * k), 0.3 * k))
    f.write("LINES 2 12\n5 0 1 2 3 4\n5 5 6 1000 8 9\n")
code, out, err = run("fit", temp("damaged.vtk"), "-o", temp("damaged-out.csv"))
check(code == 2 and "cell 1" in err and "point id 1000 out of range" in err and
      len(read_csv(temp("damaged-out.csv"))["x"]) == 41,
      "fit: a cell with a point id out of range is skipped with an error (exit 2), the other line written",
      "exit %d, %r" % (code, err.strip()))
code, out, err = run("audit", temp("damaged.vtk"))
check(code == 2 and "cell 1" in err and "out of range" in err and out.startswith("line 0: 5 points"),
      "audit: the damaged line is skipped with an error (exit 2), the other summarised",
      "exit %d, %r, %r" % (code, err.strip(), out.strip()))
code, out, err = run("audit", os.path.join(args.data, "helix.vtp"), os.path.join(args.data, "helix.vtp"))
check(code == 1 and "has no point array SpanIndex" in err and "shapesplines fit" in err,
      "audit: a data file given as CURVE is refused with a message (exit 1)", "exit %d, %r" % (code, err.strip()))

# ---------------------------------------------------------------------------- writes
# Every output that cannot be written is an error, found before the work is done.
helix_vtp = os.path.join(args.data, "helix.vtp")
missing_dir = os.path.join(args.temp, "no-such-dir")
for name in ("full.vtp", "full.csv"):
    if os.path.lexists(temp(name)):
        os.remove(temp(name))
    os.symlink("/dev/full", temp(name))  # opens, then every write fails: a full disk
write_cases = [
    (("fit", helix_vtp, "-o", os.path.join(missing_dir, "x.vtp")), "No such file or directory"),
    (("fit", helix_vtp, "-o", os.path.join(missing_dir, "x.csv")), "No such file or directory"),
    (("audit", helix_vtp, "-o", os.path.join(missing_dir, "x.vtp")), "No such file or directory"),
    (("fit", helix_vtp, "-o", args.temp), "it is a directory"),
    (("fit", helix_vtp, "-o", temp("full.vtp")), "No space left on device"),
    (("fit", helix_vtp, "-o", temp("full.csv")), "No space left on device"),
    (("audit", helix_vtp, "-o", temp("full.csv")), "No space left on device"),
]
for words, reason in write_cases:
    code, out, err = run(*words)
    output = str(words[3])
    check(code == 1 and "cannot write %s: %s" % (output, reason) in err and "wrote" not in out
          and "ERR|" not in err and "Error opening" not in err,
          "a failed write is an error: %s ... -o %s" % (words[0], os.path.basename(output)),
          "exit %d, %r, %r" % (code, err.strip(), out.strip()[-60:]))
# The up-front check finds a missing directory before the fit: no summary either.
code, out, err = run("fit", helix_vtp, "-o", os.path.join(missing_dir, "x.vtp"))
check(out == "" and not os.path.exists(missing_dir), "an unwritable output is refused before the fit",
      repr(out))
if os.path.exists(temp("never.txt")):  # left by an earlier run
    os.remove(temp("never.txt"))
code, out, err = run("fit", helix_vtp, "-o", temp("never.txt"))
check(code == 1 and not os.path.exists(temp("never.txt")), "a refused output is never created")

# ---------------------------------------------------------------------------- options
# The version is the project's (CMakeLists.txt next to Data/).
with open(os.path.join(args.data, os.pardir, "CMakeLists.txt")) as f:
    project_version = re.search(r"project\(ShapeSplines VERSION ([0-9.]+)", f.read()).group(1)
for words in (("--version",), ("fit", "--version")):
    code, out, err = run(*words)
    check(code == 0 and out == "shapesplines %s\n" % project_version and err == "",
          "shapesplines %s prints the project version %s" % (" ".join(words), project_version), repr(out))
check("--version" in run("--help")[1], "--help documents --version")
# A repeated option is an error, whichever came first, and nothing is written.
repeated = [
    (("fit", helix_vtp, "-o", temp("rep-a.vtp"), "-o", temp("rep-b.vtp")),
     "--output is given twice ('%s' and '%s')" % (temp("rep-a.vtp"), temp("rep-b.vtp"))),
    (("fit", helix_vtp, "--output", temp("rep-a.vtp"), "-o", temp("rep-b.vtp")), "--output is given twice"),
    (("fit", helix_vtp, "-o", temp("rep-a.vtp"), "--samples", "4", "--samples=8"),
     "--samples is given twice ('4' and '8')"),
    (("fit", helix_vtp, "-o", temp("rep-a.vtp"), "--closed", "--closed"), "--closed is given twice"),
    (("audit", helix_vtp, "-q", "--quiet"), "--quiet is given twice"),
]
for words, message in repeated:
    for name in ("rep-a.vtp", "rep-b.vtp"):  # left by an earlier run
        if os.path.exists(temp(name)):
            os.remove(temp(name))
    code, out, err = run(*words)
    check(code == 1 and message in err and "give each option once" in err and out == ""
          and not os.path.exists(temp("rep-a.vtp")) and not os.path.exists(temp("rep-b.vtp")),
          "repeated option refused: %s" % message.split(" (")[0], "exit %d, %r" % (code, err.strip()))
code, out, err = run("fit", helix_vtp, "-o", temp("x.vtp"), "-s", "4")
check(code == 1 and "unknown option -s" in err, "an unknown short option is refused, not read as a file",
      err.strip())

# ---------------------------------------------------------------------------- ranges
# The summary's torsion range is the data's: a helix's never reaches 0.
def printed_range(text, name):
    found = re.search(name + r" \[([^,\]]+), ([^\]]+)\]", text)
    return (float(found.group(1)), float(found.group(2))) if found else (float("nan"), float("nan"))


code, out, err = run("fit", helix_csv, "-o", temp("helix-range.csv"), "--samples", 4)
torsion = read_csv(temp("helix-range.csv"))["Torsion"]
lo, hi = printed_range(out, "torsion")
check(code == 0 and 0.15 < lo and math.isclose(lo, torsion.min(), rel_tol=1e-5)
      and math.isclose(hi, torsion.max(), rel_tol=1e-5),
      "fit: the torsion range printed is the curve's (min..max), not widened to 0",
      "printed [%g, %g], data [%g, %g]" % (lo, hi, torsion.min(), torsion.max()))
code, out, err = run("audit", helix_csv)
lo, hi = printed_range(out, "discrete torsion")
check(code == 0 and lo > 0.15 and math.isclose(lo, hi, rel_tol=1e-9),
      "audit: a regular helix's discrete torsion range, without the undefined ends' 0", out.strip())
code, out, err = run("audit", os.path.join(args.data, "akima.vtp"))
check(code == 0 and printed_range(out, "discrete torsion") == (0.0, 0.0),
      "audit: planar data's discrete torsion is [0, 0], the data's own", out.strip())

# ---------------------------------------------------------------------------- CSV line ids
# Two helices 10 apart (2 turns each, 41 points): lines 5 and 7 of length 4 pi sqrt(5) = 28.1.
pair_a = helix(20, 2)
pair_b = pair_a + [10.0, 0.0, 0.0]
pair_length = 4 * math.pi * math.sqrt(5.0)
pair_rows = [(p, 5) for p in pair_a] + [(p, 7) for p in pair_b]


def write_text(name, text, encoding="utf-8", newline="\n"):
    with open(temp(name), "w", encoding=encoding, newline=newline) as f:
        f.write(text)
    return temp(name)


def pair_csv(name, header, row, separator=",", newline="\n", bom=""):
    """The pair of helices with header (None: none) and row(x, y, z, id) giving the fields."""
    rows = ([header] if header is not None else []) + [
        separator.join(row(*(repr(float(c)) for c in p), str(k))) for p, k in pair_rows]
    return write_text(name, bom + "\n".join(rows) + "\n", newline=newline)


def summary_lines(text):
    """{line name: (samples, length)} from fit's summary."""
    return {m.group(1): (int(m.group(2)), float(m.group(3)))
            for m in re.finditer(r"^line ([^:]+): (\d+) samples, length ([^,]+),", text, re.M)}


def check_pair(what, code, out, err, output_csv, ids=("5", "7")):
    lines = summary_lines(out)
    written = read_csv(output_csv) if code == 0 else {"line_id": np.array([])}
    ok = (code == 0 and sorted(lines) == sorted(ids)
          and all(abs(length - pair_length) < 1e-3 * pair_length for _, length in lines.values())
          and list(np.unique(written["line_id"])) == [float(i) for i in ids])
    check(ok, what, "exit %d, %s, %r" % (code, lines, err.strip()[:200]))


xyz_id = lambda x, y, z, k: (x, y, z, k)
id_xyz = lambda x, y, z, k: (k, x, y, z)
# Only a line id column's meaning was wrong before: two helices read as one line of 74.6.
for header, row in (("x,y,z,id", xyz_id), ("id,x,y,z", id_xyz)):
    path = pair_csv("pair-%s.csv" % header.replace(",", ""), header, row)
    code, out, err = run("fit", path, "-o", temp("pair-out.csv"))
    check_pair("CSV header %s: two lines 5 and 7 of length %.2f each" % (header, pair_length),
               code, out, err, temp("pair-out.csv"))
for name in ("line_id", "LINE", "lineid", "Cell", "cell_id", "track", "streamline"):
    path = pair_csv("pair-alias.csv", "x,y,z," + name, xyz_id)
    code, out, err = run("fit", path, "-o", temp("pair-out.csv"))
    check_pair("a line id column named %s" % name, code, out, err, temp("pair-out.csv"))
# A line's rows need not be consecutive: the helices' rows interleaved (tracks by time).
interleaved = [row for pair in zip(pair_rows[:len(pair_a)], pair_rows[len(pair_a):]) for row in pair]
write_text("pair-interleaved.csv", "x,y,z,track\n" + "".join(
    "%r,%r,%r,%d\n" % (p[0], p[1], p[2], k) for p, k in interleaved))
code, out, err = run("fit", temp("pair-interleaved.csv"), "-o", temp("pair-out.csv"))
check_pair("interleaved rows of lines 5 and 7 make the same two lines", code, out, err, temp("pair-out.csv"))
write_text("nan-id.csv", "x,y,z,line_id\n0,0,0,1\n1,0,0,nan\n")
code, out, err = run("fit", temp("nan-id.csv"), "-o", temp("x.csv"))
check(code == 1 and "nan-id.csv:3: line id nan: line ids must be finite numbers" in err,
      "a line id that is not finite is refused", err.strip())
# Without a header: x,y,z,line_id.
path = pair_csv("pair-headerless.csv", None, xyz_id)
code, out, err = run("fit", path, "-o", temp("pair-out.csv"))
check_pair("CSV without a header, 4 columns: x,y,z,line_id", code, out, err, temp("pair-out.csv"))
# The ids reach the .vtp as the cell array LineId: read back by audit, which names
# its lines and writes its line_id column from it.
path = pair_csv("pair-ids.csv", "x,y,z,id", xyz_id)
code, out, err = run("fit", path, "-o", temp("pair-curve.vtp"), "-q")
code2, out2, err2 = run("audit", temp("pair-curve.vtp"), "-o", temp("pair-curve-shape.csv"))
written = read_csv(temp("pair-curve-shape.csv")) if code2 == 0 else {"line_id": np.array([])}
check(code == 0 and code2 == 0 and list(np.unique(written["line_id"])) == [5.0, 7.0]
      and out2.startswith("line 5: ") and "\nline 7: " in out2,
      "the .vtp curve keeps the input's ids as cell array LineId (5 and 7, not 0 and 1)",
      "exit %d/%d, %r" % (code, code2, out2.strip()[:120]))
# --line-column names any column; the other columns become point arrays.
path = pair_csv("pair-named.csv", "x,y,z,Curve,id", lambda x, y, z, k: (x, y, z, k, "1"))
code, out, err = run("fit", path, "-o", temp("pair-out.csv"), "--line-column", "curve")
check_pair("--line-column curve (any case), while 'id' becomes a point array", code, out, err,
           temp("pair-out.csv"))
check(code == 0 and np.all(read_csv(temp("pair-out.csv"))["id"] == 1), "the id column is carried as a point array")
time_rows = "".join("%r,%r,%r,%r\n" % (p[0], p[1], p[2], 0.5 * k) for k, p in enumerate(pair_a))
line_id_errors = [
    # A headerless fourth column that gives every row its own line is not a line id.
    (write_text("time.csv", time_rows), (),
     "column 4 of a CSV without a header, read as line ids, gives each of its 41 rows a line of its own: "
     "if it is not a line id, add a header row naming the columns, e.g. x,y,z,time"),
    (write_text("five.csv", "0,0,0,1,2\n1,0,0,1,2\n"), (),
     "five.csv:1: this row has 5 fields, and without a header a CSV has 3 (x,y,z) or 4 (x,y,z,line_id): "
     "add a header row naming the columns"),
    (write_text("pointid.csv", "id,x,y,z\n" + "".join("%d,%r,%r,%r\n" % ((k,) + tuple(p)) for k, p in enumerate(pair_a))),
     (), "the column 'id', read as line ids, gives each of its 41 rows a line of its own: if it numbers points"),
    (write_text("twoids.csv", "x,y,z,id,track\n0,0,0,1,1\n"), (),
     "the columns 'id' and 'track' both name line ids: choose one with --line-column"),
    (pair_csv("pair-ids.csv", "x,y,z,id", xyz_id), ("--line-column", "track"),
     "no column is named 'track' (--line-column); the header names x, y, z, id"),
    (write_text("time.csv", time_rows), ("--line-column", "time"),
     "--line-column time needs a header row naming the columns, and this CSV has none"),
    (helix_vtp, ("--line-column", "id"), "--line-column names a column of a CSV INPUT"),
]
for path, options, message in line_id_errors:
    code, out, err = run("fit", path, "-o", temp("x.csv"), *options)
    check(code == 1 and message in err and out == "",
          "line ids: %s %s refused" % (os.path.basename(path), " ".join(options)), "exit %d, %r" % (code, err.strip()))
# A CSV written by fit reads back with its ids even where it carries an 'id' array too.
write_text("ids-and-line-id.csv", "x,y,z,ID,line_id\n0,0,0,4,5\n1,0,0,4,5\n2,1,0,4,6\n3,1,1,4,6\n")
code, out, err = run("fit", temp("ids-and-line-id.csv"), "-o", temp("x.csv"))
check(code == 0 and sorted(summary_lines(out)) == ["5", "6"], "line_id wins over the other names",
      "exit %d, %r" % (code, err.strip()))

# ---------------------------------------------------------------------------- CSV dialects
# What spreadsheets write: a UTF-8 byte order mark, ';', quoted names, CRLF.
path = pair_csv("excel.csv", '"X";"Y";"Z";"Track"', xyz_id, separator=";", newline="\r\n", bom="\ufeff")
code, out, err = run("fit", path, "-o", temp("pair-out.csv"))
check_pair("UTF-8 BOM, ';' separators, quoted header, CRLF line ends", code, out, err, temp("pair-out.csv"))
path = pair_csv("tabs.csv", "x\ty\tz\tline_id", lambda x, y, z, k: ('"%s"' % x, y, z, k), separator="\t")
code, out, err = run("fit", path, "-o", temp("pair-out.csv"))
check_pair("tab separators, a quoted number", code, out, err, temp("pair-out.csv"))
# A quoted name may hold the separator; fit's CSV quotes it again and reads back.
write_text("quoted.csv", 'x,y,z,"wall, inner"\n0,0,0,1\n1,0,0,2\n2,1,0,3\n3,1,1,4\n')
code, out, err = run("fit", temp("quoted.csv"), "-o", temp("quoted-out.csv"), "-q")
code2, out2, err2 = run("audit", temp("quoted.csv"), temp("quoted-out.csv"))
with open(temp("quoted-out.csv")) as f:
    header = f.readline()
check(code == 0 and code2 == 0 and ',"wall, inner",' in header and "0 shape violations" in out2,
      "a quoted name with a comma is a point array, written quoted and read back", header[:60] + " " + err2)
dialect_errors = [
    ("extra.csv", "x,y,z\n0,0,0\n1,0,0,7\n", "extra.csv:3: this row has 4 fields, the header names 3"),
    ("short.csv", "x,y,z,line_id\n0,0,0,1\n1,0,0\n", "short.csv:3: this row has 3 fields, the header names 4"),
    ("headerless-extra.csv", "0,0,0\n1,0,0,7\n", "headerless-extra.csv:2: this row has 4 fields, the first row has 3"),
    ("duplicate.csv", "x,y,z,X\n0,0,0,1\n", "duplicate.csv:1: the header names 'X' twice (columns 1 and 4"),
    ("duplicate-array.csv", "x,y,z,radius,Radius\n0,0,0,1,1\n", "the header names 'Radius' twice (columns 4 and 5"),
    ("noname.csv", "x,y,z,\n0,0,0,\n", "noname.csv:1: column 4 of the header has no name"),
    ("noxyz.csv", "a;b;c\n0;0;0\n", "noxyz.csv:1: the header must name the columns x, y and z; it names a, b, c"),
    ("comma.csv", "x;y;z\n0,5;1;2\n", "comma.csv:2: column 1 (x) is not a number: '0,5' (decimal commas are not read"),
    ("quote.csv", 'x,y,z\n0,0,"1\n', 'quote.csv:2: a double quote is not closed'),
]
for name, text, message in dialect_errors:
    code, out, err = run("fit", write_text(name, text), "-o", temp("x.csv"))
    check(code == 1 and message in err and out == "", "CSV refused: %s" % name, "exit %d, %r" % (code, err.strip()))
code, out, err = run("fit", write_text("utf16.csv", "x,y,z\n0,0,0\n1,1,1\n", encoding="utf-16"), "-o", temp("x.csv"))
check(code == 1 and "the text is UTF-16: save the CSV as UTF-8" in err, "a UTF-16 CSV is refused", err.strip())
help_text = " ".join(run("--help")[1].split())
rules = ("byte order mark is skipped", "LF or CRLF", "the separator is a tab if the first row has one, else ';'",
         "double quotes", "--line-column NAME", "line_id, line, lineid, id, cell, cell_id, track or streamline",
         "Without a header a CSV has 3 columns (x,y,z) or 4 (x,y,z,line_id)", "cell array LineId")
check(all(rule in help_text for rule in rules), "--help states the CSV rules",
      "missing %s" % [r for r in rules if r not in help_text])

# ---------------------------------------------------------------------------- audit: the curve's own data
# A curve audited against data it was not fitted to is an error, never "-1 violations".
akima_vtp = os.path.join(args.data, "akima.vtp")
code, out, err = run("fit", helix_vtp, "-o", temp("helix-curve.vtp"), "-q")
if os.path.exists(temp("mismatch.csv")):  # left by an earlier run
    os.remove(temp("mismatch.csv"))
code, out, err = run("audit", akima_vtp, temp("helix-curve.vtp"), "-o", temp("mismatch.csv"))
check(code == 1 and "CURVE %s does not match INPUT %s (line 0: the curve's spans or closure differ"
      % (temp("helix-curve.vtp"), akima_vtp) in err and "curve: not audited (it does not match the data)" in out
      and "-1" not in out and not os.path.exists(temp("mismatch.csv")),
      "audit: a curve of other data is an error (exit 1) and nothing is written", "exit %d, %r, %r" % (code, out, err))
code, out, err = run("audit", os.path.join(args.data, "aorta-centerline.vtp"), temp("helix-curve.vtp"), "-q")
check(code == 1 and "does not match INPUT" in err and "lines 1 in CURVE, 2 in INPUT" in err,
      "audit: a curve with another number of lines is an error (exit 1), even with -q", err.strip())
code, out, err = run("audit", helix_vtp, temp("helix-curve.vtp"), "--closed", "-q")
check(code == 1 and "does not match INPUT" in err and "the same --closed" in err and out == "",
      "audit -q: an open curve audited as closed is an error (exit 1)", err.strip())
# The fit skipped the NaN line: its curve does not pair with the data line by line.
code, out, err = run("fit", temp("nan.csv"), "-o", temp("nan-curve.vtp"), "-q")
code, out, err = run("audit", temp("nan.csv"), temp("nan-curve.vtp"))
check(code == 1 and "lines 1 in CURVE, 2 in INPUT" in err and "a fit that skipped lines wrote fewer" in err,
      "audit: the curve of a fit that skipped a line does not match its data (exit 1)", err.strip())
code, out, err = run("audit", helix_vtp, temp("helix-curve.vtp"))
check(code == 0 and "curve: 0 shape violations" in out, "audit: the curve with its own data is audited", out.strip())
# An approximation's knots are not the data points: only fit audits it, and audit says so.
code, out, err = run("fit", helix_vtp, "-o", temp("helix-approximation.vtp"), "-q", "--family", "quintic",
                     "--mode", "approximate")
code, out, err = run("audit", helix_vtp, temp("helix-approximation.vtp"))
check(code == 1 and "approximates INPUT" in err and "fit audited the approximation against its reference polygon"
      in err and "curve: not audited (it approximates the data" in out,
      "audit: an approximation is not audited, and audit says why (exit 1)", "exit %d, %r" % (code, err.strip()))

# ---------------------------------------------------------------------------- fit's and audit's counts
# fit audits its curve on its own sampling (both sides of each knot, rounding known);
# audit reads the written samples. Each count says which it is, and audit repeats fit's.
aorta_vtp = os.path.join(args.data, "aorta-centerline.vtp")
code, out, err = run("fit", aorta_vtp, "-o", temp("aorta16.vtp"), "--samples", 16)
fit_counts = [int(c) for c in re.findall(r"shape violations (\d+) \(fit's audit\)$", out, re.M)]
code2, out2, err2 = run("audit", aorta_vtp, temp("aorta16.vtp"))
audit_rows = re.findall(r"curve: (\d+) shape violations in the written samples \(collinearity (\d+), "
                        r"convexity (\d+)\+(\d+), coplanarity (\d+), torsion sign (\d+)\+(\d+)\); "
                        r"fit's audit: (\d+)$", out2, re.M)
check(code == 0 and code2 == 0 and len(fit_counts) == 2 and len(audit_rows) == 2
      and all(int(r[0]) == sum(int(c) for c in r[1:7]) for r in audit_rows)
      and [int(r[7]) for r in audit_rows] == fit_counts,
      "fit --samples 16 and audit of its curve: each count labelled, audit's adds up, fit's repeated by audit",
      "fit %s, audit %s" % (fit_counts, [(r[0], r[7]) for r in audit_rows]))
code, out, err = run("fit", aorta_vtp, "-o", temp("aorta16.csv"), "--samples", 16, "-q")
code2, out2, err2 = run("audit", aorta_vtp, temp("aorta16.csv"))
check(code2 == 0 and out2.count("in the written samples") == 2 and "fit's audit" not in out2,
      "audit of a CSV curve (no cell arrays): only the count of the written samples",
      out2.strip().splitlines()[0][-120:])
help_text = " ".join(run("--help")[1].split())
check("16 samples a span whatever the output's sampling, each knot seen from both of its spans" in help_text
      and "audit can only read the written samples" in help_text, "--help explains the two counts")

# ---------------------------------------------------------------------------- stdin and stdout
def read_bytes(path):
    with open(path, "rb") as f:
        return f.read()


def csv_text(text):
    """The columns of CSV text with a header, like read_csv."""
    rows = text.splitlines()
    values = np.loadtxt(rows[1:], delimiter=",", ndmin=2)
    return {name: values[:, i] for i, name in enumerate(rows[0].split(","))}


# -o - : the curve as CSV on stdout, nothing else; the summary on stderr.
pair_path = pair_csv("pair-stdin.csv", "x,y,z,id", xyz_id)
code, out, err = run_with_input(read_bytes(pair_path), "fit", "-", "-o", "-")
curve = csv_text(out) if code == 0 else {"line_id": np.array([])}
lines = summary_lines(err)
check(code == 0 and list(np.unique(curve["line_id"])) == [5.0, 7.0] and len(curve["x"]) == 802
      and sorted(lines) == ["5", "7"] and all(abs(l - pair_length) < 1e-3 * pair_length for _, l in lines.values())
      and "wrote stdout (2 lines, 802 samples)" in err,
      "fit - -o -: CSV from stdin, the curve's CSV alone on stdout, the summary on stderr",
      "exit %d, %r" % (code, err.strip()[:200]))
code2, out2, err2 = run("fit", pair_path, "-o", temp("pair-file.csv"), "-q")
check(code2 == 0 and out.encode() == read_bytes(temp("pair-file.csv")), "stdout holds what the .csv file holds")
# A pipe: fit's CSV on stdout is audit's CURVE on stdin.
code2, out2, err2 = run_with_input(out.encode(), "audit", pair_path, "-")
check(code2 == 0 and out2.count("curve: 0 shape violations in the written samples") == 2,
      "fit ... -o - | audit INPUT -: the curve read back from stdin and audited", err2.strip())
code2, out2, err2 = run_with_input(read_bytes(pair_path), "fit", "-", "-o", temp("pair-named-out.csv"), "-q",
                                   "--line-column", "ID")
check(code2 == 0 and list(np.unique(read_csv(temp("pair-named-out.csv"))["line_id"])) == [5.0, 7.0],
      "--line-column applies to a CSV on stdin", err2.strip())
# VTK XML and legacy VTK on stdin are told from CSV by their first words.
for name in (helix_vtp, temp("two.vtk")):
    code, out, err = run_with_input(read_bytes(name), "fit", "-", "-o", "-", "-q")
    code2, out2, err2 = run("fit", name, "-o", temp("from-file.csv"), "-q")
    check(code == 0 and code2 == 0 and out.encode() == read_bytes(temp("from-file.csv")),
          "fit - with %s on stdin: the same curve as from the file" % os.path.basename(name), err.strip())
code, out, err = run("audit", pair_path, "-o", "-", "-q")
check(code == 0 and csv_text(out)["DiscreteCurvature"].shape == (82,) and err == "",
      "audit -o -: the discrete shape as CSV on stdout", err.strip())
with open("/dev/full", "w") as full:
    result = subprocess.run([args.exe, "fit", pair_path, "-o", "-", "-q"], stdout=full, stderr=subprocess.PIPE,
                            text=True, timeout=120)
check(result.returncode == 1 and "cannot write stdout: No space left on device" in result.stderr,
      "a failed write on stdout is an error (exit 1)", result.stderr.strip())
stdin_errors = [
    (b"<?xml version='1.0'?><VTKFile", ("fit", "-", "-o", temp("x.csv")), "shapesplines: cannot read stdin:"),
    (read_bytes(helix_vtp), ("fit", "-", "-o", temp("x.csv"), "--line-column", "id"),
     "--line-column names a column of a CSV INPUT, and stdin is not one"),
    (b"", ("fit", "-", "-o", temp("x.csv")), "no points read from stdin"),
    (b"x,y,z\n0,0,0\n1,0,0,1\n", ("fit", "-", "-o", temp("x.csv")), "stdin:3: this row has 4 fields"),
    (read_bytes(pair_path), ("audit", "-", "-"), "INPUT and CURVE cannot both be - (stdin)"),
]
for data, words, message in stdin_errors:
    code, out, err = run_with_input(data, *words)
    check(code == 1 and message in err and "ERR|" not in err, "stdin refused: %s" % message, "exit %d, %r" % (code, err))
help_text = " ".join(run("--help")[1].split())
check("INPUT or CURVE - reads stdin: VTK XML if it starts with <?xml or <VTKFile" in help_text
      and "-o - writes CSV on stdout, and the summary goes to stderr" in help_text, "--help documents - and -o -")

if failures:
    print("\n%d checks FAILED:\n  " % len(failures) + "\n  ".join(failures))
    sys.exit(1)
print("\nAll command-line checks passed.")
