#!/usr/bin/python3
"""Regenerates the figures and tables of docs/phong-vs-reference.md with gloss-cli: every metal
preset of the 24 against its measured metal (Real-Time Rendering, 4th ed., Table 9.2; bronze
against copper, said so), the fitted constants, the residual floor over roughness, lobe plots,
A/B images (preset | best Phong | reference | heat map), the 4x exponent rule against the best
model-to-model fit, and what an environment light would ask instead.

Usage: scripts/phong_vs_reference.py [GLOSS_CLI]   (default build/src/cli/gloss-cli)
Writes docs/images/phong-vs-reference/*.png and prints the tables as Markdown on stdout.
Run with Debian's /usr/bin/python3 (python3-matplotlib).
"""
import json
import math
import os
import struct
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # no display; must precede pyplot
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CLI = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build/src/cli/gloss-cli")
OUT = os.path.join(ROOT, "docs/images/phong-vs-reference")
ENV = dict(os.environ, GLOSS_ASSETS=os.path.join(ROOT, "assets"))

# The metal presets of the OpenGL/VRML table and the measured metal each is held against.
METALS = [("brass", "brass"), ("bronze", "copper"), ("chrome", "chromium"),
          ("copper", "copper"), ("gold", "gold"), ("silver", "silver")]


def preset_exponent(name):
    """The preset's Phong exponent (the table's fraction x 128), from gloss-cli presets."""
    out = subprocess.run([CLI, "presets"], env=ENV, check=True, capture_output=True, text=True)
    for line in out.stdout.splitlines()[1:]:
        words = line.split()
        if words[0] == name:
            return float(words[-1])
    raise KeyError(name)


def matching_roughness(phong_alpha):
    """The roughness whose GGX width a matches the preset's highlight: Walter's Blinn-Phong
    exponent 2 / a^2 - 2 with the 4x rule's Blinn-Phong exponent 4 alpha; roughness = sqrt(a)."""
    a = math.sqrt(2.0 / (4.0 * phong_alpha + 2.0))
    return round(math.sqrt(a), 2)


def fit(tmp, *args):
    path = os.path.join(tmp, "fit.json")
    subprocess.run([CLI, "fit", *args, "--json", path], env=ENV, check=True, capture_output=True)
    with open(path) as f:
        return json.load(f)


def lobe(tmp, *args, elevation=45):
    path = os.path.join(tmp, "lobe.csv")
    subprocess.run([CLI, "fit", *args, "--lobe-csv", path, "--elevation", str(elevation)],
                   env=ENV, check=True, capture_output=True)
    data = np.genfromtxt(path, delimiter=",", names=True)
    return data


def read_pfm(path):
    with open(path, "rb") as f:
        assert f.readline().strip() == b"PF"
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4")
    return np.flipud(data.reshape(h, w, 3))


def render(tmp, material, physical):
    scene = {
        "camera": {"eye": [0, 0.6, 3.6], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 38},
        "background": [0.08, 0.09, 0.12], "ambient": [0.2, 0.2, 0.2],
        "lights": [{"position": [4, 5, 6]}],
        "materials": {"m": material},
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}],
        "render": {"width": 160, "height": 120, "spp": 4},
    }
    path = os.path.join(tmp, "scene.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    pfm = os.path.join(tmp, "out.pfm")
    args = [CLI, "render", path, "--pfm", pfm] + (["--physical"] if physical else [])
    subprocess.run(args, env=ENV, check=True, capture_output=True)
    return read_pfm(pfm)


def material_of(result, preset=None, reference=None):
    m = {"preset": preset} if preset else {}
    if result is not None:
        m.update({"diffuse": result["diffuse"], "specular": result["specular"],
                  "shininess": result["shininess"]})
    if reference:
        m["reference"] = reference
    return m


def rgb(c, digits=3):
    return ", ".join(f"{x:.{digits}g}" for x in c)


def main():
    os.makedirs(OUT, exist_ok=True)
    tmp = tempfile.mkdtemp()
    rows, env_rows, lobes, ab = [], [], [], []
    for preset, metal in METALS:
        alpha = preset_exponent(preset)
        r = matching_roughness(alpha)
        ref = ["--reference", metal, "--roughness", str(r)]
        phong = fit(tmp, *ref, "--preset", preset)
        blinn = fit(tmp, *ref, "--model", "blinn-phong")
        light = fit(tmp, *ref, "--metric", "lightness")
        rim = fit(tmp, *ref, "--max-angle", "90")
        normalised = fit(tmp, *ref, "--energy-normalize")
        rows.append((preset, metal, alpha, r, phong, blinn, light, rim, normalised))
        env_rows.append((preset, metal, r, phong))
        lobes.append((preset, metal, r, lobe(tmp, *ref, "--preset", preset),
                      lobe(tmp, *ref, "--model", "blinn-phong")))
        reference = {"kind": metal, "roughness": r}
        images = [render(tmp, material_of(None, preset), False),
                  render(tmp, material_of(phong, preset), False),
                  render(tmp, material_of(None, preset, reference), True)]
        ab.append((preset, metal, r, images))

    print("## Metal presets against their measured metals\n")
    print("| preset | measured metal | roughness | preset as it is: l2 rel, L* | best Phong kd; ks;"
          " alpha | l2 rel, L* | best Blinn-Phong alpha; l2 rel, L* | Phong fit on L*: alpha;"
          " l2 rel, L* | with the rims (90 degrees): l2 rel |")
    print("|---|---|---|---|---|---|---|---|---|")
    for preset, metal, alpha, r, p, b, li, rim, _ in rows:
        note = metal + (" (no bronze row: copper)" if preset == "bronze" else "")
        print(f"| {preset} (alpha {alpha:g}) | {note} | {r} | "
              f"{p['preset_residual']['l2_relative']:.3f}, {p['preset_residual']['lightness']:.1f} | "
              f"{rgb(p['diffuse'])}; {rgb(p['specular'])}; {p['shininess']:.4g} | "
              f"{p['residual']['l2_relative']:.3f}, {p['residual']['lightness']:.1f} | "
              f"{b['shininess']:.4g}; {b['residual']['l2_relative']:.3f}, "
              f"{b['residual']['lightness']:.1f} | {li['shininess']:.4g}; "
              f"{li['residual']['l2_relative']:.3f}, {li['residual']['lightness']:.1f} | "
              f"{rim['residual']['l2_relative']:.3f} |")
    print("\n## Energy normalisation on (the same lobes; ks in the normalised formula)\n")
    print("| preset | ks (off) | ks (on) | alpha | l2 rel |")
    print("|---|---|---|---|---|")
    for preset, _, _, _, p, _, _, _, n in rows:
        print(f"| {preset} | {rgb(p['specular'])} | {rgb(n['specular'])} | {n['shininess']:.4g} |"
              f" {n['residual']['l2_relative']:.3f} |")

    print("\n## Under an environment\n")
    print("| preset | measured metal, roughness | preset ks | F0 | env ks (mean albedo) | head-on |"
          " at 80 degrees | env alpha (Phong) | point-light alpha |")
    print("|---|---|---|---|---|---|---|---|---|")
    presets = {}
    out = subprocess.run([CLI, "presets"], env=ENV, check=True, capture_output=True, text=True)
    for line in out.stdout.splitlines()[1:]:
        w = line.split()
        presets[w[0]] = [float(x) for x in w[7:10]]
    for preset, metal, r, p in env_rows:
        e = p["environment"]
        print(f"| {preset} | {metal}, {r} | {rgb(presets[preset])} | {rgb(p['reference']['f0'])} |"
              f" {rgb(e['ks'])} | {rgb(e['albedo_normal'])} | {rgb(e['albedo_80deg'])} |"
              f" {e['shininess']:.4g} | {p['shininess']:.4g} |")

    # The residual floor over roughness, gold: the best lobe of each model in each metric (each
    # fitted on the metric it is measured in), with and without the rims.
    roughness = [0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0]
    floor = {}
    for metric in ("l2", "lightness"):
        for model in ("phong", "blinn-phong"):
            for cut in ("80", "90"):
                floor[(model, cut, metric)] = [
                    fit(tmp, "--reference", "gold", "--roughness", str(r), "--model", model,
                        "--max-angle", cut, "--metric", metric)["residual"] for r in roughness]
    print("\n## The residual floor (gold; the best lobe's l2 relative when fitted on l2 / its "
          "lightness error when fitted on lightness)\n")
    keys = [(m, c) for m in ("phong", "blinn-phong") for c in ("80", "90")]
    print("| roughness | " + " | ".join(f"{m}, within {c} degrees" for m, c in keys) + " |")
    print("|---" * (len(keys) + 1) + "|")
    for i, r in enumerate(roughness):
        print(f"| {r} | " + " | ".join(
            f"{floor[(m, c, 'l2')][i]['l2_relative']:.3f} / "
            f"{floor[(m, c, 'lightness')][i]['lightness']:.1f}" for m, c in keys) + " |")

    # Model to model: the best Blinn-Phong exponent for a Phong one and back, the 4x rule.
    alphas = [2, 5, 10, 20, 50, 100, 200, 500, 1000, 5000]
    rule = {"to-blinn": [], "to-phong": []}
    for a in alphas:
        scene_alpha = {"to-blinn": (a, "phong", "blinn-phong"), "to-phong": (4 * a, "blinn-phong",
                                                                              "phong")}
        for key, (source_alpha, src, dst) in scene_alpha.items():
            res = fit(tmp, "--preset", "white_plastic", "--from", src, "--model", dst,
                      "--source-shininess", str(source_alpha))
            rule[key].append((source_alpha, res))
    print("\n## Model to model (white_plastic's kd 0.55, ks 0.7 at each exponent)\n")
    print("| source | best target alpha (ratio) | best l2 rel | 4x rule alpha | 4x rule l2 rel |")
    print("|---|---|---|---|---|")
    for key in rule:
        for source_alpha, res in rule[key]:
            src = res["source"]["model"]
            print(f"| {src} {source_alpha:g} | {res['shininess']:.4g} "
                  f"({res['shininess'] / source_alpha:.3f}) | {res['residual']['l2_relative']:.4f} |"
                  f" {res['rule']['shininess']:g} | {res['rule_residual']['l2_relative']:.4f} |")

    # The measured materials files' table (scripts/make-measured-materials fits the same).
    print("\n## The measured materials (Phong, l2, point lights, energy normalisation off)\n")
    print("| metal | roughness | kd | ks | alpha | l2 rel | L* | Blinn-Phong alpha; l2 rel, L* |")
    print("|---|---|---|---|---|---|---|---|")
    for metal in ("gold", "silver", "aluminium", "copper", "chromium", "brass"):
        for r in ("0.1", "0.2", "0.3", "0.5"):
            p = fit(tmp, "--reference", metal, "--roughness", r)
            b = fit(tmp, "--reference", metal, "--roughness", r, "--model", "blinn-phong")
            print(f"| {metal} | {r} | {rgb(p['diffuse'])} | {rgb(p['specular'])} |"
                  f" {p['shininess']:.4g} | {p['residual']['l2_relative']:.3f} |"
                  f" {p['residual']['lightness']:.1f} | {b['shininess']:.4g};"
                  f" {b['residual']['l2_relative']:.3f}, {b['residual']['lightness']:.1f} |")

    plot_lobes(lobes)
    plot_ab(ab)
    plot_floor(roughness, floor)
    plot_rule(rule)
    plot_grazing(tmp)


def plot_lobes(lobes):
    fig, axes = plt.subplots(2, 3, figsize=(11, 6.2), sharex=True)
    for ax, (preset, metal, r, d, b) in zip(axes.flat, lobes):
        ax.semilogy(d["theta_deg"], d["reference"], "k-", lw=2, label=f"{metal} r={r} (GGX)")
        ax.semilogy(d["theta_deg"], d["fit"], color="#E69F00", lw=1.5, label="best Phong (l2)")
        ax.semilogy(b["theta_deg"], b["fit"], color="#0072B2", lw=1.2, ls="--",
                    label="best Blinn-Phong (l2)")
        ax.semilogy(d["theta_deg"], d["preset"], color="#777777", lw=1.2, ls=":",
                    label=f"preset {preset} (Phong)")
        ax.set_ylim(1e-3, max(d["reference"].max(), d["fit"].max()) * 2)
        ax.set_title(f"{preset} vs measured {metal}" + (" (no bronze row)" if preset == "bronze"
                                                        else ""), fontsize=9)
        ax.grid(True, which="major", lw=0.3)
        ax.legend(fontsize=6.5, loc="lower center")
    fig.supxlabel("outgoing angle from the normal, degrees (the light 45 degrees above the surface, "
                  "on the left; the mirror direction at +45)", fontsize=9)
    fig.supylabel("luminance under a unit light", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "lobes.png"), dpi=80)


def plot_ab(ab):
    fig, axes = plt.subplots(len(ab), 4, figsize=(8, 1.6 * len(ab)))
    for row, (preset, metal, r, (p, fitted, ref)) in zip(axes, ab):
        diff = np.abs(fitted - ref).max(axis=2)
        scale = max(diff.max(), 1e-6)
        for ax, img, title in zip(row[:3], (p, fitted, ref),
                                  (f"preset {preset}", "best Phong (l2)", f"{metal} r={r}")):
            ax.imshow(np.clip(img, 0, 1))
            ax.set_title(title, fontsize=7)
        ax = row[3]
        ax.imshow(diff, cmap="inferno", vmin=0, vmax=scale)
        ax.set_title(f"|best Phong - ref|, 0..{scale:.3g}", fontsize=7)
        for ax in row:
            ax.axis("off")
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "ab.png"), dpi=80)


def plot_floor(roughness, floor):
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.4))
    colours = {"phong": "#E69F00", "blinn-phong": "#0072B2"}
    for (model, cut, metric), values in floor.items():
        ls = "-" if cut == "80" else ":"
        label = f"{model}, light and view within {cut} degrees"
        if metric == "l2":
            a.plot(roughness, [v["l2_relative"] for v in values], color=colours[model], ls=ls,
                   label=label)
        else:
            b.plot(roughness, [v["lightness"] for v in values], color=colours[model], ls=ls,
                   label=label)
    a.set_title("gold: best lobe on l2, its l2 relative to the reference's", fontsize=9)
    b.set_title("gold: best lobe on lightness, its error in L*", fontsize=9)
    for ax in (a, b):
        ax.set_xlabel("roughness")
        ax.grid(True, lw=0.3)
        ax.set_ylim(bottom=0)
    a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "floor.png"), dpi=80)


def plot_grazing(tmp):
    """Gold at roughness 0.3 in the plane of incidence for a high, a low and a grazing light:
    where the best Phong and the best Blinn-Phong lobes part ways."""
    ref = ["--reference", "gold", "--roughness", "0.3"]
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.3), sharey=True)
    for ax, e in zip(axes, (60, 30, 10)):
        p = lobe(tmp, *ref, elevation=e)
        b = lobe(tmp, *ref, "--model", "blinn-phong", elevation=e)
        ax.semilogy(p["theta_deg"], p["reference"], "k-", lw=2, label="gold r=0.3 (GGX)")
        ax.semilogy(p["theta_deg"], p["fit"], color="#E69F00", lw=1.5, label="best Phong (l2)")
        ax.semilogy(b["theta_deg"], b["fit"], color="#0072B2", lw=1.2, ls="--",
                    label="best Blinn-Phong (l2)")
        ax.axvline(90 - e, color="k", lw=0.6, ls=":")
        ax.set_title(f"light {e} degrees above the surface (mirror at {90 - e})", fontsize=9)
        ax.set_ylim(1e-3, 300)
        ax.grid(True, lw=0.3)
    axes[0].legend(fontsize=7, loc="lower left")
    axes[0].set_ylabel("luminance under a unit light")
    fig.supxlabel("outgoing angle from the normal, degrees", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "grazing.png"), dpi=80)


def plot_rule(rule):
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.4))
    ta = [s for s, _ in rule["to-blinn"]]
    a.semilogx(ta, [r["shininess"] / s for s, r in rule["to-blinn"]], "o-", color="#0072B2",
               label="best Blinn-Phong / Phong")
    tb = [s / 4 for s, _ in rule["to-phong"]]
    a.semilogx(tb, [s / r["shininess"] for s, r in rule["to-phong"]], "s--", color="#E69F00",
               label="Blinn-Phong / best Phong")
    a.axhline(4, color="k", lw=0.8, ls=":", label="the 4x rule")
    a.set_xlabel("Phong exponent")
    a.set_ylabel("exponent ratio")
    a.set_ylim(0, 5)
    a.legend(fontsize=7)
    b.semilogx(ta, [r["residual"]["l2_relative"] for _, r in rule["to-blinn"]], "o-",
               color="#0072B2", label="best Blinn-Phong for Phong")
    b.semilogx(ta, [r["rule_residual"]["l2_relative"] for _, r in rule["to-blinn"]], "o:",
               color="#0072B2", label="4x rule")
    b.semilogx(tb, [r["residual"]["l2_relative"] for _, r in rule["to-phong"]], "s-",
               color="#E69F00", label="best Phong for Blinn-Phong")
    b.semilogx(tb, [r["rule_residual"]["l2_relative"] for _, r in rule["to-phong"]], "s:",
               color="#E69F00", label="x1/4 rule")
    b.set_xlabel("Phong exponent (Blinn-Phong: 4x)")
    b.set_ylabel("l2, relative")
    b.legend(fontsize=7)
    for ax in (a, b):
        ax.grid(True, lw=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "rule.png"), dpi=80)


if __name__ == "__main__":
    main()
