#!/usr/bin/env python3
# -----------------------------------------------------------------------------
# mpsFsiFoam: bench/timeStep/levels.py - the table of one ladder of runs of
# bench/timeStep/Allrun: each figure at each level, the last halving's
# change, the observed order p and the extrapolated value of the three finest
# levels (refinement ratio 2):
#   e1 = f2 - f1, e2 = f3 - f2 (f3 the finest); where e1 and e2 have one sign
#   and |e2| < |e1|: p = log2(e1/e2), f_inf = f3 + e2/(2^p - 1);
#   otherwise no order ("-": the levels do not converge monotonically).
#
# Usage: levels.py [-curves <folder>] <ladder> <level>=<run folder> ...
#   (several folders of one level: lattice offsets, their mean is taken and
#   the spread of the mean force printed); -curves writes each level's
#   history (its first folder's) to <folder>/<ladder>-<level>.dat: time,
#   F/(rho V^3 t) as a 0.5 ms running mean and, for the elastic wedge, the
#   30 mm wet strain (the mean of the left and right gauges, microstrain)
# -----------------------------------------------------------------------------
import math
import os
import subprocess
import sys


def entry(path, key):
    """An entry of an OpenFOAM dictionary (foamDictionary -value)"""
    out = subprocess.run(
        ["foamDictionary", "-entry", key, "-value", path],
        capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit("levels.py: no entry %s in %s" % (key, path))
    return out.stdout.strip()


def columns(path, names):
    """Named columns of a postProcessing .dat file (its last '# Time' header)"""
    header, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                words = line[1:].split()
                if words and words[0] == "Time":
                    header = words
                continue
            v = line.split()
            if v:
                rows.append(v)
    if header is None:
        sys.exit("levels.py: %s has no '# Time' header" % path)
    missing = [n for n in names if n not in header]
    if missing:
        sys.exit("levels.py: %s has no column %s; valid: %s"
                 % (path, ", ".join(missing), " ".join(header)))
    idx = [header.index(n) for n in names]
    return [[float(r[i]) for r in rows] for i in idx]


def mean(v):
    return sum(v)/len(v) if v else float("nan")


def window(t, f, t0, t1):
    return [y for x, y in zip(t, f) if t0 <= x < t1 + 1e-12]


def roughness(t, F, t0, t1):
    """rms of F about its running mean over +-0.5 ms, over the mean of F"""
    d, s = [], []
    j0 = j1 = 0
    run = 0.0
    n = len(t)
    for i in range(n):
        while j1 < n and t[j1] <= t[i] + 0.0005 + 1e-12:
            run += F[j1]
            j1 += 1
        while t[j0] < t[i] - 0.0005 - 1e-12:
            run -= F[j0]
            j0 += 1
        if t0 <= t[i] <= t1:
            d.append(F[i] - run/(j1 - j0))
            s.append(F[i])
    if not s:
        return float("nan")
    return math.sqrt(mean([x*x for x in d]))/abs(mean(s))


def running(t, f, half):
    """The running mean of f over +-half"""
    out = []
    j0 = j1 = 0
    s = 0.0
    for i in range(len(t)):
        while j1 < len(t) and t[j1] <= t[i] + half + 1e-12:
            s += f[j1]
            j1 += 1
        while t[j0] < t[i] - half - 1e-12:
            s -= f[j0]
            j0 += 1
        out.append(s/(j1 - j0))
    return out


def curves(run, path):
    """A run's history: t, F/(rho V^3 t) (0.5 ms running mean) [, strain]"""
    rho = float(entry(os.path.join(run, "constant/mpsProperties"), "rho"))
    motion = entry(os.path.join(run, "constant/structureProperties"),
                   "bodyMotion/velocity")
    V = abs(float(motion.replace("(", " ").replace(")", " ").split()[2]))
    t, F = columns(
        os.path.join(run, "postProcessing/structureForces/0/force.dat"),
        ["Time", "Fy"])
    c = running(t, [f/(rho*V**3*x) if x > 0 else 0.0 for x, f in zip(t, F)],
                0.00025)
    strain = os.path.join(run, "postProcessing/strainProbes/0/strain.dat")
    e = None
    if os.path.isfile(strain):
        ts, l30, r30 = columns(strain, ["Time", "left30_wet", "right30_wet"])
        if len(ts) == len(t):
            e = [0.5e6*(a + b) for a, b in zip(l30, r30)]
    with open(path, "w") as f:
        f.write("# time [s]  F/(rho V^3 t), 0.5 ms running mean"
                + ("  30 mm wet strain [1e-6]" if e else "") + "\n")
        for i in range(len(t)):
            f.write("%.8g %.6g" % (t[i], c[i])
                    + (" %.6g" % e[i] if e else "") + "\n")


def figures(run):
    """The figures of one run folder, by name (in table order)"""
    rho = float(entry(os.path.join(run, "constant/mpsProperties"), "rho"))
    motion = entry(os.path.join(run, "constant/structureProperties"),
                   "bodyMotion/velocity")
    V = abs(float(motion.replace("(", " ").replace(")", " ").split()[2]))
    t, F = columns(
        os.path.join(run, "postProcessing/structureForces/0/force.dat"),
        ["Time", "Fy"])
    c = [f/(rho*V**3*x) if x > 0 else 0.0 for x, f in zip(t, F)]
    end = t[-1]
    elastic = os.path.isfile(
        os.path.join(run, "postProcessing/strainProbes/0/strain.dat"))
    fig = {}
    if elastic:
        fig["F/(rho V^3 t), 2-3 ms"] = mean(window(t, c, 0.002, 0.003))
        fig["roughness 4-20 ms [%]"] = 100*roughness(t, F, 0.004, 0.02)
    else:
        fig["F/(rho V^3 t), 5-20 ms"] = mean(window(t, c, 0.005, 0.02))
        fig["roughness 4-20 ms [%]"] = 100*roughness(t, F, 0.004, 0.02)
        sim = os.path.join(run, "postProcessing/wallPressure/pressureSimilarity.dat")
        if os.path.isfile(sim):
            ratios = []
            with open(sim) as f:
                for line in f:
                    if line.startswith("#"):
                        continue
                    v = [float(x) for x in line.split()]
                    if v[0] < 0.8 and v[3] > 1 and v[1] != 0:
                        ratios.append(v[2]/v[1])
            fig["Cp scatter [%]"] = 100*mean(ratios)
    k = 1
    while (k + 1)*0.001 <= end + 1e-9:
        fig["F/(rho V^3 t), %d-%d ms" % (k, k + 1)] = \
            mean(window(t, c, 0.001*k, 0.001*(k + 1) - 1e-9))
        k += 1
    if elastic:
        ts, l30, r30, l120, r120 = columns(
            os.path.join(run, "postProcessing/strainProbes/0/strain.dat"),
            ["Time", "left30_wet", "right30_wet", "left120_wet", "right120_wet"])
        for at in (0.005, 0.0075, 0.01, 0.015, 0.02, 0.025, 0.03):
            if at > end + 1e-9:
                continue
            for name, a, b in (("30", l30, r30), ("120", l120, r120)):
                e = [0.5e6*(x + y) for x, y in zip(a, b)]
                fig["strain %s mm wet, %g ms [1e-6]" % (name, 1000*at)] = \
                    mean(window(ts, e, at - 0.0005 + 1e-9, at))
    return fig


def order(f):
    """Last halving's change [%], observed order and extrapolated value of
    the three finest of the levels f (coarsest first)"""
    if len(f) < 2 or any(math.isnan(x) for x in f[-3:]):
        return "", "", ""
    change = "%+.1f%%" % (100*(f[-1] - f[-2])/abs(f[-1])) if f[-1] else ""
    if len(f) < 3:
        return change, "", ""
    e1, e2 = f[-2] - f[-3], f[-1] - f[-2]
    if e1*e2 <= 0 or abs(e2) >= abs(e1):
        return change, "-", "-"
    p = math.log2(e1/e2)
    return change, "%.2f" % p, "%.4g" % (f[-1] + e2/(2**p - 1))


def main():
    args = sys.argv[1:]
    curveDir = None
    if len(args) >= 2 and args[0] == "-curves":
        curveDir = args[1]
        args = args[2:]
    if len(args) < 2:
        sys.exit("Usage: levels.py [-curves <folder>] <ladder>"
                 " <level>=<run folder> ...")
    ladder = args[0]
    levels, runs = [], {}
    for arg in args[1:]:
        name, run = arg.split("=", 1)
        if name not in runs:
            levels.append(name)
            runs[name] = []
            if curveDir:
                curves(run, os.path.join(curveDir,
                                         "%s-%s.dat" % (ladder, name)))
        runs[name].append(figures(run))
    names = list(runs[levels[0]][0].keys())
    # the figures a level's runs all have, in order
    for name in levels:
        for fig in runs[name]:
            names = [n for n in names if n in fig]
    value = {lv: {n: mean([fig[n] for fig in runs[lv]]) for n in names}
             for lv in levels}

    print("\n### %s\n" % ladder)
    print("| figure | " + " | ".join(levels)
          + " | last halving | order | extrapolated |")
    print("|---" * (len(levels) + 4) + "|")
    for n in names:
        f = [value[lv][n] for lv in levels]
        change, p, ext = order(f)
        digits = "%.0f" if "strain" in n else "%.2f"
        print("| %s | %s | %s | %s | %s |"
              % (n, " | ".join(digits % x for x in f), change, p, ext))
    if any(len(runs[lv]) > 1 for lv in levels):
        first = names[0]
        spread = []
        for lv in levels:
            v = [fig[first] for fig in runs[lv]]
            spread.append("%.1f%%" % (100*(max(v) - min(v))/abs(mean(v))))
        print("\n%s over %d lattice offsets, spread (max - min)/mean: %s"
              % (first, len(runs[levels[0]]), ", ".join(spread)))


if __name__ == "__main__":
    main()
