#!/usr/bin/env python3
"""A mode-count study: how many vibration modes does the modal boom need, with and without static
correction modes?

Runs the reference crane with a modal boom of k = 1 … K vibration modes, each with and without the
static correction modes, and a fine nodal boom at a tight tolerance as the reference. A run's error
is the worst, over the crane's motions and loads, of RMS(x − x_ref) / (standard deviation of x_ref)
after the wave ramp. The motions are displacements from each model's own static equilibrium (as in
timeseries.csv), so this error measures the dynamics; `ffrf compare` also judges the static part
(docs/validation.md). Charts the error and the solver work against k.

    PYTHONPATH=build/python python3 examples/python/mode_count.py --out results/mode_count

--quick runs k ≤ 3 over 30 s (the test suite runs it so).
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402

import ffrf  # noqa: E402

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
JUDGED = ["cargo_heave", "cargo_pitch", "crane_heave", "crane_pitch", "wire_tension", "joint_moment"]


def worst_error(run, reference, start):
    window = reference.time >= start
    errors = {}
    for name in JUDGED:
        x, x_ref = run.outputs[name][window], reference.outputs[name][window]
        scale = np.std(x_ref)
        errors[name] = np.sqrt(np.mean((x - x_ref) ** 2)) / scale if scale > 0 else 0.0
    name = max(errors, key=errors.get)
    return errors[name], name


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=str(REPOSITORY / "cases" / "paper_floating_crane.toml"))
    parser.add_argument("--out", default=".", help="folder for mode_count.png and mode_count.csv")
    parser.add_argument("--quick", action="store_true", help="k = 1..3 over 30 s")
    args = parser.parse_args()

    duration = 30.0 if args.quick else 120.0
    counts = range(1, 4 if args.quick else 9)
    scene = ffrf.load_scene(args.scene)
    reference = ffrf.run(scene, boom="nodal", elements=32, rtol=1e-8, atol=1e-8, duration=duration)
    start = reference.summary["statistics_window"]["ramp_end_s"]  # errors after the wave ramp
    print(f"reference: {reference.model}, rtol 1e-8, {reference.solver['steps']} steps")

    rows = ["modes,static_modes,error,worst_output,work,wall_s"]
    results = {True: [], False: []}
    for static in (False, True):
        for k in counts:
            run = ffrf.run(scene, boom="modal", modes=k, static_modes=static, duration=duration)
            error, output = worst_error(run, reference, start)
            work = run.work  # RHS evaluations × state size
            results[static].append((k, error, work))
            rows.append(f"{k},{static},{error:.4g},{output},{work},{run.solver['wall_time_s']:.4g}")
            print(f"{run.model}: error {error:.3g} ({output}), work {work}")

    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    (out / "mode_count.csv").write_text("\n".join(rows) + "\n")
    figure, (error_axes, work_axes) = plt.subplots(1, 2, figsize=(10, 4))
    for static, marker in ((False, "o"), (True, "s")):
        k, error, work = np.array(results[static]).T
        label = "with static modes" if static else "vibration modes only"
        error_axes.semilogy(k, error, marker=marker, label=label)
        work_axes.plot(k, work, marker=marker, label=label)
    error_axes.set_xlabel("vibration modes k")
    error_axes.set_ylabel("worst RMS error / std of the reference")
    error_axes.set_title(f"Modal boom against nodal N=32 ({duration:g} s)")
    work_axes.set_xlabel("vibration modes k")
    work_axes.set_ylabel("solver work [RHS evaluations × state size]")
    for axes in (error_axes, work_axes):
        axes.xaxis.set_major_locator(MaxNLocator(integer=True))
        axes.grid(True, which="both", alpha=0.3)
        axes.legend()
    figure.tight_layout()
    figure.savefig(out / "mode_count.png", dpi=120)
    print(f"wrote {out / 'mode_count.png'} and {out / 'mode_count.csv'}")


if __name__ == "__main__":
    main()
