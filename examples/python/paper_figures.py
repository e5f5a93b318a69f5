#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Notebook-style tour of the kinstab Python module: the paper's figures from a script.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/paper_figures.py [OUT_DIR]

Writes three PNGs (default: docs/python/):
  1. gamma-surface.png: gamma_c(A, f) of the 1-DOF slab for the three envelopes
     (Furgerson 1980, ch. IV: the collapse-factor surfaces).
  2. acrit-vs-codes.png: A_crit(f), the smallest floor acceleration that collapses the slab,
     against the lateral force ratios F_top / w_top of the codes for the paper's 16-story
     building (ch. V).
  3. record-run.png: the 1971 Pacoima Dam 164 deg record through the building's floor filter
     (T = 1 s, 2 %; ch. V, Figs. 25-27), scaled to its critical peak, and the slab's response.
"""

# %% Setup
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import kinstab  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "python"
OUT.mkdir(parents=True, exist_ok=True)
PROJECT = json.loads((ROOT / "resources" / "examples" / "paper-16-story.json").read_text())

# %% 1. The gamma_c surfaces: one sweep per envelope, all cores, NumPy arrays back.
amplitudes = np.arange(0.60, 1.6001, 0.01)
frequencies = np.arange(0.25, 2.5001, 0.0125)
surfaces = {}
for envelope in ("fast", "moderate", "slow"):
    surfaces[envelope] = kinstab.surface(amplitudes, frequencies, envelope=envelope)
    s = surfaces[envelope]
    print(f"surface {envelope}: {s.gamma_c.size} points in {s.wall_time_s:.2f} s")
top = max(np.percentile(s.gamma_c[s.gamma_c > 0], 99) for s in surfaces.values())
fig, axes = plt.subplots(1, 3, figsize=(15, 4.6), sharey=True, constrained_layout=True)
for ax, (envelope, s) in zip(axes, surfaces.items()):
    shown = np.where(s.gamma_c > 0, s.gamma_c, np.nan)  # white where the slab stays
    mesh = ax.pcolormesh(s.frequencies, s.amplitudes, shown, shading="nearest", cmap="viridis",
                         vmin=0, vmax=top)
    ax.set_title(f"{envelope} envelope (mu = 0.6, t* = 0.099 s)")
    ax.set_xlabel("frequency f (Hz)")
axes[0].set_ylabel("amplitude A (g)")
fig.colorbar(mesh, ax=axes, label="collapse factor gamma_c = tau_ref / tau_c (white: stays)")
fig.savefig(OUT / "gamma-surface.png", dpi=110)
plt.close(fig)

# %% 2. A_crit(f) against the codes' lateral force ratios for the paper's building.
f = np.arange(0.25, 3.0001, 0.0625)
fig, ax = plt.subplots(figsize=(8.5, 5), constrained_layout=True)
for envelope in ("fast", "moderate", "slow"):
    a_crit = kinstab.critical(f, envelope=envelope, scan_step=0.01, tolerance=1e-4)
    ax.plot(f, a_crit, label=f"A_crit, {envelope} envelope")
results = kinstab.codes(PROJECT["building"], **PROJECT["codes"])
for (key, r), style in zip(results.items(), ("--", "-.", ":", (0, (5, 1)), (0, (1, 3)))):
    ax.axhline(r["top_ratio"], color="0.3", linestyle=style,
               label=f"{r['title']}: F_top/w_top = {r['top_ratio']:.3f}")
ax.axhline(0.6, color="tab:red", linewidth=0.8, label="mu = 0.6 (no slip below)")
period = PROJECT["building"]["period_s"]
ax.axvline(1.0 / period, color="0.6", linewidth=0.8, label=f"f = 1/T = {1.0 / period:g} Hz")
ax.set_xlabel("frequency f (Hz)")
ax.set_ylabel("floor acceleration (g)")
ax.set_title("Critical amplitude of the slab vs. code lateral force ratios (16-story building)")
ax.set_ylim(0, 3.5)
ax.legend(fontsize=7.5, loc="upper left")
fig.savefig(OUT / "acrit-vs-codes.png", dpi=110)
plt.close(fig)

# %% 3. A record run: the floor motion at its critical peak, and the slab's response.
record = ROOT / "resources" / "records" / "RSN77_SFERN_PUL164.AT2"
probe = kinstab.simulate_record(str(record), floor_period=1.0, damping=0.02, critical=True)
peak = probe["critical_peak"]
print(f"record: floor motion peak {abs(probe['motion'].peak):.3f} g, critical peak {peak:.4f} g")
run = kinstab.simulate_record(str(record), floor_period=1.0, damping=0.02,
                              amplitude=peak * 1.001, history_step=0.05)
ground, h = run["ground"], run["history"]
tstar = 0.099
fig, (top, mid, bottom) = plt.subplots(3, 1, figsize=(9, 7.5), sharex=True,
                                       constrained_layout=True)
top.plot(ground.time, ground.samples, color="0.4", linewidth=0.6)
top.set_ylabel("ground (g)")
top.set_title(f"{ground.name}; floor (T = 1 s, 2 %) scaled to {run['amplitude']:.3f} g "
              f"= critical peak x 1.001", fontsize=9)
motion = run["motion"]  # the floor motion, unscaled
mid.plot(motion.time, motion.samples * run["scale_factor"], linewidth=0.6)
mid.axhline(0.6, color="tab:red", linewidth=0.7)
mid.axhline(-0.6, color="tab:red", linewidth=0.7)
mid.set_ylabel("floor a(t) (g)")
bottom.plot(h["tau"] * tstar, h["delta"], color="tab:purple")
bottom.axhline(1.0, color="k", linewidth=0.7, linestyle="--")
bottom.axhline(-1.0, color="k", linewidth=0.7, linestyle="--")
bottom.set_ylabel("slip delta / (d/2)")
bottom.set_xlabel("time t (s)")
bottom.set_title(f"outcome: {run['outcome']}, tau_c = {run['tau_c']:.1f} "
                 f"(t_c = {run['tau_c'] * tstar:.2f} s)")
bottom.set_xlim(0, 20)
fig.savefig(OUT / "record-run.png", dpi=110)
plt.close(fig)
print(f"figures in {OUT}")
