#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Work-precision plot (SVG, no dependencies) from the CSV of `kinstab-cli precision -o`.

usage: plot-precision.py FILE.csv OUT.svg [CASE_PREFIX]
One curve per case, joined in tolerance order: error against the median CPU time, log-log. CASE_PREFIX keeps the cases
whose name starts with it (e.g. "planar").
"""
import csv
import math
import sys

W, H, L, R, T, B = 720, 480, 80, 200, 30, 60
COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2"]


def curves(path, prefix):
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if not row["case"].startswith(prefix):
                continue
            t, e = float(row["cpu_median_s"]), float(row["error"])
            if t > 0 and e > 0 and math.isfinite(t) and math.isfinite(e):
                out.setdefault(row["case"], []).append((t, e, row["setting"]))
    return out


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    data = curves(sys.argv[1], sys.argv[3] if len(sys.argv) == 4 else "")
    if not data:
        sys.exit("no finite rows in " + sys.argv[1])
    pts = [p for c in data.values() for p in c]
    lx = [math.floor(math.log10(min(p[0] for p in pts))), math.ceil(math.log10(max(p[0] for p in pts)))]
    ly = [math.floor(math.log10(min(p[1] for p in pts))), math.ceil(math.log10(max(p[1] for p in pts)))]
    sx = lambda t: L + (math.log10(t) - lx[0]) / (lx[1] - lx[0]) * (W - L - R)
    sy = lambda e: H - B - (math.log10(e) - ly[0]) / (ly[1] - ly[0]) * (H - T - B)
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    for k in range(lx[0], lx[1] + 1):
        x = sx(10.0**k)
        svg.append(f'<line x1="{x:.1f}" y1="{T}" x2="{x:.1f}" y2="{H - B}" stroke="#ddd"/>')
        svg.append(f'<text x="{x:.1f}" y="{H - B + 16}" text-anchor="middle">1e{k}</text>')
    for k in range(ly[0], ly[1] + 1):
        y = sy(10.0**k)
        svg.append(f'<line x1="{L}" y1="{y:.1f}" x2="{W - R}" y2="{y:.1f}" stroke="#ddd"/>')
        svg.append(f'<text x="{L - 6}" y="{y + 4:.1f}" text-anchor="end">1e{k}</text>')
    svg.append(f'<rect x="{L}" y="{T}" width="{W - L - R}" height="{H - T - B}" fill="none" stroke="black"/>')
    svg.append(f'<text x="{(L + W - R) / 2}" y="{H - 20}" text-anchor="middle">median CPU time per case, s (one curve per case, in tolerance order)</text>')
    svg.append(f'<text x="20" y="{(T + H - B) / 2}" text-anchor="middle" transform="rotate(-90 20 {(T + H - B) / 2})">error</text>')
    for i, (name, c) in enumerate(sorted(data.items())):
        col = COLOURS[i % len(COLOURS)]
        path = " ".join(f"{sx(t):.1f},{sy(e):.1f}" for t, e, _ in c)
        svg.append(f'<polyline points="{path}" fill="none" stroke="{col}" stroke-width="2"/>')
        for t, e, s in c:
            svg.append(f'<circle cx="{sx(t):.1f}" cy="{sy(e):.1f}" r="3" fill="{col}"><title>{s}</title></circle>')
        svg.append(f'<text x="{W - R + 10}" y="{T + 16 + 18 * i}" fill="{col}">{name}</text>')
    svg.append("</svg>")
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main()
