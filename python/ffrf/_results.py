"""What ffrf's functions return: plain Python values and numpy arrays.

Every result has ``summary``, the command line's JSON summary of the same study as a dict (what
``ffrf COMMAND --json`` prints, or its ``summary.json``), and ``text``, the report the command line
prints. The attributes beside them are the parts most scripts want, taken from the study's own
results (time series, responses, frequencies as numpy arrays) or read out of ``summary``.
"""

import json

import numpy as np


class Result:
    """A study's result: ``summary`` (dict, the command line's JSON) and ``text`` (its report)."""

    def __init__(self, raw):
        raw = dict(raw)
        self.summary = json.loads(raw.pop("summary"))
        self.text = raw.pop("text")
        for name, value in raw.items():
            setattr(self, name, value)

    def __repr__(self):
        return f"<ffrf.{type(self).__name__}: {self._headline()}>"

    def _headline(self):
        return self.text.strip().splitlines()[0] if self.text.strip() else ""


class Run(Result):
    """One model's run (``ffrf.run``).

    ``time`` [s] and ``outputs[name]`` are numpy arrays of every output channel of the model's
    output-channel table, by the channel's name (``"cargo_heave"``), in the units of the command
    line's timeseries.csv (``units[name]``; its column is ``columns[name]``, ``"cargo_heave_m"``);
    motions are displacements from the static equilibrium, as there. ``model`` is the boom model's
    label, ``warnings`` the modelling advice the command line prints, ``state_size`` the ODE state's
    size (2 × minimal coordinates) and ``work`` the solver work, RHS evaluations × state size (the
    measure the verdicts decide by). ``boom_stress`` is the stresses along the boom over the run
    (boom_stress.csv's columns; None without a boom): numpy arrays over the sections, ``position``
    [m] from the heel, the extremes ``axial_force_min``/``_max`` [N], ``bending_moment_min``/``_max``
    [N m] and ``stress_min``/``stress_max`` [MPa] of the fibre stress, and ``peak_time`` [s].
    """

    @property
    def statics(self):
        """The static equilibrium (dict, summary.json's ``static_equilibrium``)."""
        return self.summary.get("static_equilibrium")

    @property
    def solver(self):
        """The solver's statistics (dict: steps, evaluations, wall time, ...)."""
        return self.summary.get("solver")

    @property
    def detections(self):
        """What the failure detectors found (list of dicts: kind, time_s, cause, remedy, ...)."""
        return self.summary.get("detections", [])

    @property
    def provenance(self):
        """How the run was obtained (scene, values set beside it, integrator, tolerances, version, date)."""
        return self.summary.get("provenance")

    def _headline(self):
        return f"{self.model}, {len(self.time)} samples to t = {self.time[-1]:g} s" if len(self.time) else self.model


def _model_row(model):
    errors = model.get("errors_to_reference", {})
    worst = errors.get("worst_output")
    verdict = model.get("verdict", {})
    return {
        "label": model.get("model"),
        "boom": model.get("boom"),
        "elastic_dof": model.get("elastic_dof"),
        "error": errors.get("worst_normalized_rms"),
        "worst_output": worst,
        "static_error": errors.get(worst, {}).get("static_error") if worst else None,
        "dynamic_error": errors.get(worst, {}).get("dynamic_error") if worst else None,
        "passed": verdict.get("passed"),
        "wall_speedup": verdict.get("wall_speedup"),
        "work_speedup": verdict.get("work_speedup"),
        "work": model.get("work"),
    }


class Comparison(Result):
    """The boom models compared against the converged reference (``ffrf.compare``).

    ``verdict`` is the verdict sentence, ``cheapest`` the cheapest model that passes (dict, or None),
    ``models`` one dict per compared model (label, error = the worst normalized RMS error over the
    judged outputs, worst_output, its static and dynamic parts, passed, wall_speedup, work_speedup,
    work), ``reference`` the converged reference; ``radiation`` the radiation models' comparison of a
    scene with BEM coefficients (text; empty otherwise).
    """

    @property
    def verdict(self):
        return self.summary["verdict"]["sentence"]

    @property
    def cheapest(self):
        return self.summary["verdict"]["cheapest"]

    @property
    def tolerance(self):
        return self.summary["verdict"]["tolerance"]

    @property
    def models(self):
        return [_model_row(model) for model in self.summary["models"]]

    @property
    def reference(self):
        return self.summary["reference"]

    def _headline(self):
        return self.verdict


class Recommendation(Result):
    """The cheapest model within the tolerance (``ffrf.recommend``): ``chosen`` (dict: label, boom,
    elements, modes, static_modes, stiffening, integrator, rtol, error, work, wall_seconds and ``command``, the
    ``ffrf run`` line that reproduces it; None when no candidate met the tolerance), ``decision`` (the
    sentence), ``candidates`` (summary.json's list)."""

    @property
    def decision(self):
        return self.summary.get("decision")

    @property
    def candidates(self):
        return self.summary.get("candidates", [])

    def _headline(self):
        return self.decision or ""


class RaoModel:
    """One boom model's frequency response: ``angular_frequencies`` [rad/s] and ``periods`` [s]
    (numpy), ``responses[output]`` complex numpy arrays per metre of wave amplitude (``units[output]``),
    ``natural_modes`` (list of dicts: angular_frequency, period, damping_ratio, dominant)."""

    def __init__(self, raw):
        self.label = raw["label"]
        self.angular_frequencies = raw["angular_frequencies"]
        self.periods = 2.0 * np.pi / self.angular_frequencies
        self.responses = raw["responses"]
        self.units = raw["units"]
        self.natural_modes = raw["natural_modes"]

    def amplitude(self, output):
        """|RAO| of an output (numpy array, per metre of wave amplitude)."""
        return np.abs(self.responses[output])

    def phase_deg(self, output):
        """The phase of an output relative to the wave elevation at x = 0 [deg]."""
        return np.degrees(np.angle(self.responses[output]))

    def __repr__(self):
        return f"<ffrf.RaoModel {self.label}: {len(self.angular_frequencies)} frequencies>"


class RaoResult(Result):
    """RAOs and natural modes (``ffrf.rao``): ``models`` is a list of ``RaoModel``, one per boom
    model (rigid, nodal, modal unless one was named); ``model(label)`` finds one by its label."""

    def __init__(self, raw):
        raw = dict(raw)
        models = raw.pop("models")
        super().__init__(raw)
        self.models = [RaoModel(model) for model in models]

    def model(self, label):
        for model in self.models:
            if model.label == label:
                return model
        raise KeyError(f"{label!r}: no such model; the models are {[m.label for m in self.models]}")

    def _headline(self):
        return ", ".join(model.label for model in self.models)


class Modes(Result):
    """The boom's natural modes (``ffrf.modes``): ``frequencies_hz`` and ``analytic_hz`` (numpy; NaN
    where no analytic value exists), ``kinds`` ("bending", "axial", "rigid"), ``orders``, ``shapes``
    (numpy, free DOFs × modes, M-normalised), ``warnings``."""

    @property
    def relative_errors(self):
        return np.abs(self.frequencies_hz - self.analytic_hz) / self.analytic_hz

    def _headline(self):
        return ", ".join(f"{f:.4g} Hz" for f in self.frequencies_hz)


class Sweep(Result):
    """The accuracy–speed sweep (``ffrf.sweep``): ``rows`` (one dict per configuration, the command
    line's sweep.csv row: model, integrator, status, worst_error, wall_seconds, work, ...), ``csv`` (that
    file's text); ``column(name)`` gives one field of every row as a numpy array."""

    def column(self, name):
        values = [row[name] for row in self.rows]
        if all(isinstance(v, (int, float)) or v is None for v in values):
            return np.array([np.nan if v is None else v for v in values], dtype=float)
        return np.array(values, dtype=object)


class Stability(Result):
    """The stability map (``ffrf.stability``): ``summary`` holds every section's cells and numbers,
    ``text`` the Markdown report."""


class Operability(Result):
    """The operability table (``ffrf.operability``): ``cells`` (one dict per sea state: hs, tp,
    heading, status, passed, governing criterion, utilisation, model, failure), ``warnings``;
    ``grid(field, heading)`` gives a field as a numpy array over Tp (rows) × Hs (columns)."""

    def grid(self, field="utilisation", heading="following"):
        cells = [cell for cell in self.cells if cell["heading"] == heading]
        hs = sorted({cell["hs"] for cell in cells})
        tp = sorted({cell["tp"] for cell in cells})
        table = np.full((len(tp), len(hs)), np.nan)
        for cell in cells:
            value = cell[field]
            table[tp.index(cell["tp"]), hs.index(cell["hs"])] = np.nan if value is None else float(value)
        return np.array(hs), np.array(tp), table


class Baseline(Result):
    """A recorded regression baseline (``ffrf.baseline_record``): ``summary`` is the baseline file's
    document (what ``out`` was written with)."""


class BaselineCheck(Result):
    """A run judged against a baseline (``ffrf.baseline_check``): ``passed``, ``failures``, and
    ``summary["deviations"]`` for every quantity."""

    def _headline(self):
        return "passed" if self.passed else f"{self.failures} quantities outside their tolerances"
