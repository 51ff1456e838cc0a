#------------------------------------------------------------------------------
# mpsFsiFoam: bench/loads/wallNoise.py - where the rigid wedge's load noise
# lives along its right panel (doc/studies/2026-12-03-slamming-loads.md), from the wall particles' pressures
# written every step.
#
# Usage: pvpython bench/loads/wallNoise.py <case> <l0>
#   <case> a bench/loads rigid run with every step's wall snapshot, e.g.
#     bench/loads/Allrun rigid 0.005 edge \
#         C:functions.wallPressure.writeControl=timeStep \
#         C:functions.wallPressure.writeInterval=1 C:functions.wallPressure.probes!
#   (without probes the function object writes postProcessing/wallPressure/
#   <t>/wallPressure.dat at each of its own write times).
# Over 6-19 ms, S(t) = l0 sum p_i over the right panel's wall particles, and
# its high-passed part (S less its 1 ms running mean):
#   - by the particles' distance behind the wetted edge (the outermost wall
#     particle with p > 0): each band's share of S and of the variance of
#     high-passed S (the covariance of the band's part with the whole);
#   - the coherence of the interior (wet from 10 ms on and 8 l0 or more
#     behind the edge then): var(sum)/sum(var) of its particles' high-passed
#     pressures, 1 for independent particles, their number for one pulse;
#   - the interior's high-passed load about the steps where the edge
#     advances, averaged over those steps, in its rms.
# ParaView's Python (pvpython) brings numpy; the project's VTK is ParaView's.
#------------------------------------------------------------------------------
import os
import sys

import numpy as np

if len(sys.argv) != 3:
    sys.exit("Usage: pvpython wallNoise.py <case> <l0>")
case, l0 = sys.argv[1], float(sys.argv[2])
t0, t1 = 0.006, 0.019
base = os.path.join(case, "postProcessing", "wallPressure")
times = sorted(
    (float(t), t) for t in os.listdir(base) if t[0].isdigit()
)
T = np.array([t for t, _ in times])
if len(T) < 100 or np.median(np.diff(T)) > 1e-4:
    sys.exit(f"{base}: not every step written (see Usage)")
rows = [
    np.loadtxt(os.path.join(base, name, "wallPressure.dat"), comments="#")
    for _, name in times
]

# The keel: the lowest wall particle; the right panel: x beyond it
xKeel = rows[0][np.argmin(rows[0][:, 1]), 0]
bands = [(0, 1), (1, 2), (2, 4), (4, 8), (8, np.inf)]
parts = np.zeros((len(T), len(bands)))
edge = np.zeros(len(T))
for k, a in enumerate(rows):
    yKeel = a[:, 1].min()
    r = a[a[:, 0] > xKeel]
    s = np.hypot(r[:, 0] - xKeel, r[:, 1] - yKeel)
    wet = r[:, 2] > 0
    if not wet.any():
        continue
    edge[k] = s[wet].max()
    behind = (edge[k] - s)/l0
    for b, (lo, hi) in enumerate(bands):
        parts[k, b] = l0*r[(behind >= lo) & (behind < hi), 2].sum()

dt = np.median(np.diff(T))
width = max(1, int(round(0.001/dt)))


def highPass(x):
    return x - np.convolve(x, np.ones(width)/width, mode="same")


window = (T >= t0) & (T <= t1)
S = parts.sum(axis=1)
hS = highPass(S)[window]
meanS = S[window].mean()
print(f"{os.path.basename(os.path.abspath(case))}: {len(T)} steps;"
      f" S about its 1 ms running mean: rms {np.sqrt(np.mean(hS**2))/meanS:.1%} of its mean")
print("  behind the edge [l0]   share of S   share of the noise   its rms / mean S")
for b, (lo, hi) in enumerate(bands):
    hb = highPass(parts[:, b])[window]
    print(f"  {lo:g}-{hi:g}".ljust(24)
          + f"{parts[window, b].mean()/meanS:9.1%}"
          + f"{np.mean(hb*hS)/np.mean(hS**2):17.1%}"
          + f"{np.sqrt(np.mean(hb**2))/meanS:18.1%}")

# Coherence of the interior: particles tracked by their row (a rigid wall
# keeps its order)
n = min(len(a) for a in rows)
P = np.array([a[:n, 2] for a in rows])
k10 = np.argmin(abs(T - 0.010))
a10 = rows[k10][:n]
s10 = np.hypot(a10[:, 0] - xKeel, a10[:, 1] - a10[:, 1].min())
interior = (
    (a10[:, 0] > xKeel) & ((edge[k10] - s10)/l0 >= 8)
    & (P[T >= 0.010] > 0).all(axis=0)
)
late = (T > 0.0105) & (T <= t1)
if interior.sum() > 1:
    H = np.array([highPass(P[:, j]) for j in np.where(interior)[0]])[:, late]
    print(f"  interior (wet from 10 ms, 8 l0 or more behind the edge):"
          f" {interior.sum()} particles, var(sum)/sum(var)"
          f" {np.var(H.sum(axis=0))/np.var(H, axis=1).sum():.1f}")
else:
    print("  interior: fewer than two particles wet throughout 10-19 ms")

# The interior's load about the edge's advances
events = [
    k for k in range(1, len(T))
    if edge[k] > edge[k - 1] + 1e-9 and t0 < T[k] < t1 - 20*dt
]
if len(events) < 2:
    sys.exit("  the edge advances fewer than twice in 6-19 ms: no average")
hI = highPass(parts[:, -1])
rmsI = np.sqrt(np.mean(hI[window]**2))
lags = range(-10, 21, 2)
print(f"  the edge advances {len(events)} times"
      f" (every {1e3*(T[events[-1]] - T[events[0]])/(len(events) - 1):.2f} ms);"
      " the interior's high-passed load about an advance, in its rms:")
print("    step " + "".join(f"{L:6d}" for L in lags))
print("    mean " + "".join(
    f"{np.mean([hI[k + L] for k in events])/rmsI:+6.2f}" for L in lags))
