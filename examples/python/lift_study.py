#!/usr/bin/env python3
"""A parametric lift study: boom angle × cargo mass on the reference floating crane.

For every combination, ffrf recommends the cheapest boom model and integrator whose worst error over
the crane's motions and loads stays within the tolerance against a converged reference, and the
study charts what that model costs (solver work, RHS evaluations × state size, the measure the
recommendation decides by) and which model it is. Scenes are values: each lift is the reference
scene with two keys set, checked like the file.

    PYTHONPATH=build/python python3 examples/python/lift_study.py --out results/lift_study

--quick runs a small grid with short records (the test suite runs it so).
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # charts to files, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import ffrf  # noqa: E402

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(REPOSITORY / "cases" / "paper_floating_crane.toml"))
    parser.add_argument("--out", default=".", help="folder for lift_study.png and lift_study.csv")
    parser.add_argument("--tolerance", type=float, default=0.01)
    parser.add_argument("--quick", action="store_true", help="a 2 × 2 grid of 30-s records")
    args = parser.parse_args()

    angles = [50.0, 65.0] if args.quick else [45.0, 50.0, 55.0, 60.0, 65.0, 70.0]
    masses = [800.0, 2000.0] if args.quick else [800.0, 1300.0, 2000.0, 2600.0]
    duration = 30.0 if args.quick else 120.0
    scene = ffrf.load_scene(args.scene)

    work = np.full((len(masses), len(angles)), np.nan)
    labels = {}
    rows = ["boom_angle_deg,cargo_mass_t,model,integrator,rtol,error,work,wall_s"]
    for i, mass in enumerate(masses):
        for j, angle in enumerate(angles):
            lift = scene.with_values({"boom.angle": f"{angle:g} deg", "cargo.mass": f"{mass:g} t"})
            rec = ffrf.recommend(lift, tolerance=args.tolerance, duration=duration)
            chosen = rec.chosen
            if chosen is None:
                print(f"{angle:g} deg, {mass:g} t: no model within {args.tolerance:g} ({rec.decision})")
                continue
            work[i, j] = chosen["work"]
            labels[(i, j)] = chosen["label"].split(",")[0]
            rows.append(f"{angle:g},{mass:g},{labels[(i, j)]},{chosen['integrator']},{chosen['rtol']:g},"
                        f"{chosen['error']:.4g},{chosen['work']:.6g},{chosen['wall_seconds']:.4g}")
            print(f"{angle:g} deg, {mass:g} t: {chosen['label']}, error {chosen['error']:.3g}")

    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "lift_study.csv").write_text("\n".join(rows) + "\n")
    figure, axes = plt.subplots(figsize=(8, 5))
    for i, mass in enumerate(masses):
        axes.plot(angles, work[i], marker="o", label=f"cargo {mass:g} t")
        for j, angle in enumerate(angles):
            if (i, j) in labels:
                axes.annotate(labels[(i, j)], (angle, work[i, j]), fontsize=7, xytext=(3, 3), textcoords="offset points")
    if np.nanmax(work) > 10.0 * np.nanmin(work):
        axes.set_yscale("log")
    axes.set_xlabel("boom angle [deg]")
    axes.set_ylabel("solver work of the recommended model\n[RHS evaluations × state size]")
    axes.margins(x=0.15, y=0.15)
    axes.set_title(f"Cheapest boom model within {100 * args.tolerance:g} % ({scene.name}, {duration:g} s)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(out / "lift_study.png", dpi=120)
    print(f"wrote {out / 'lift_study.png'} and {out / 'lift_study.csv'}")


if __name__ == "__main__":
    main()
