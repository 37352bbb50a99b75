#!/usr/bin/env python3
"""One sentence's viseme weights against its phoneme boundaries (docs/speech.md).

The weights are fapc's own output (the curves JSON of `fapc compile sentence.fml -o -.json`),
the phonemes the engine's (`speech_bench --phonemes en TEXT`); this script only draws them:
  python3 docs/speech/plot.py curves.json phonemes.txt > docs/speech/sentence.svg
"""
import json
import sys

COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
           "#7f7f7f", "#bcbd22", "#17becf", "#393b79", "#637939", "#8c6d31", "#843c39"]


def main():
    curves = json.load(open(sys.argv[1]))["curves"]
    phonemes = [line.split() for line in open(sys.argv[2]) if line.strip()]
    end = max([float(p[2]) for p in phonemes] + [t for k, v in curves.items() if k.startswith("viseme.") for t, _ in v])
    width, height, left, top, plot_h = 960, 340, 60, 30, 220
    x = lambda t: left + (width - left - 20) * t / end
    y = lambda w: top + plot_h * (1 - w / 63)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           'font-family="sans-serif" font-size="11">', '<rect width="100%" height="100%" fill="white"/>',
           f'<rect x="{left}" y="{top}" width="{width - left - 20}" height="{plot_h}" fill="none" stroke="#999"/>',
           f'<text x="{left}" y="18" font-size="13">viseme weights (0..63) against the phoneme boundaries '
           '(grey lines, eSpeak NG names below); time in seconds</text>']
    for name, begin, stop, _ in phonemes:
        b = float(begin)
        out.append(f'<line x1="{x(b):.1f}" x2="{x(b):.1f}" y1="{top}" y2="{top + plot_h}" stroke="#ccc"/>')
        mid = (float(begin) + float(stop)) / 2
        out.append(f'<text x="{x(mid):.1f}" y="{top + plot_h + 14}" text-anchor="middle">{name}</text>')
    for t in range(0, int(end * 10) + 1):
        out.append(f'<text x="{x(t / 10):.1f}" y="{top + plot_h + 30}" text-anchor="middle" fill="#666">{t / 10:g}</text>')
    legend = 0
    for i, (target, points) in enumerate(sorted(k for k in curves.items() if k[0].startswith("viseme."))):
        colour = COLOURS[i % len(COLOURS)]
        path = " ".join(f"{x(t):.1f},{y(v):.1f}" for t, v in points)
        out.append(f'<polyline fill="none" stroke="{colour}" stroke-width="1.8" points="{path}"/>')
        out.append(f'<text x="{left + 70 * legend}" y="{height - 8}" fill="{colour}">{target}</text>')
        legend += 1
    out.append("</svg>")
    print("\n".join(out))


main()
