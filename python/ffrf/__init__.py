"""ffrf: a floating crane with an elastic boom — rigid, nodal and modal boom models compared.

The studies of the ``ffrf`` command line as Python functions, on scenes as values::

    import ffrf, numpy as np
    scene = ffrf.load_scene("cases/paper_floating_crane.toml")
    lift = scene.with_values({"boom.angle": "55 deg", "cargo.mass": "2400 t"})
    run = ffrf.run(lift, boom="modal", modes=2, static_modes=True, duration=60.0)
    run.time, run.outputs["cargo_heave"]

Every function takes the scene first and keyword arguments named after the command line's options
(``--rtol`` is ``rtol``, ``--reference-elements`` is ``reference_elements``); a keyword left out
(or None) takes the same default as the option, and a value is checked by the same code with the
same message (``SettingError`` naming the keyword). Results are plain Python values and numpy
arrays, with ``summary``: the command line's JSON summary of the same study as a dict.
Long calls release the GIL and stop cleanly on Ctrl-C (``KeyboardInterrupt``), leaving no files
behind. docs/python.md describes every function.
"""

from ._errors import BaselineFileError, Error, SceneError, SettingError, SolverFailure
from ._results import (Baseline, BaselineCheck, Comparison, Modes, Operability, RaoModel, RaoResult, Recommendation,
                       Result, Run, Stability, Sweep)
from ._values import override_text
from . import _ffrf

__all__ = ["Scene", "load_scene", "scene_from_text", "run", "compare", "recommend", "rao", "modes", "sweep",
           "stability", "operability", "baseline_record", "baseline_check", "Error", "SceneError", "SettingError",
           "SolverFailure", "BaselineFileError", "Result", "Run", "Comparison", "Recommendation", "RaoResult",
           "RaoModel", "Modes", "Sweep", "Stability", "Operability", "Baseline", "BaselineCheck"]


class Scene:
    """A scene: a scene file's text and the values given beside it (``with_values``).

    A scene is a value: ``with_values`` returns a new scene and leaves this one as it is. Each new
    scene is loaded again from the same text with all its values, so the whole scene is checked —
    units, ranges, the keys across each other, the physics — exactly as ``ffrf check --set`` checks
    it; a problem raises ``SceneError`` naming the key, the value and the valid range.
    """

    def __init__(self, value, text, values):
        self._value = value
        self._text = text
        self._values = dict(values)
        facts = _ffrf.scene_facts(value)
        self.path = facts["path"]
        self.name = facts["name"]
        self.description = facts["description"]
        self.kind = facts["kind"]  # "crane", "hub" or "beam"
        self.warnings = facts["warnings"]
        self.facts = facts

    @property
    def values(self):
        """The values given beside the file, by key (a copy)."""
        return dict(self._values)

    @property
    def text(self):
        """The scene file's text."""
        return self._text

    def with_values(self, values=None, **keywords):
        """A new scene with these keys set, as ``--set KEY=VALUE`` sets them: ``{"boom.angle": "55 deg",
        "cargo.mass": "2400 t", "boom.elements": 8}``. A value is a str as on the command line (with
        its unit where it has one), a number (SI), a bool or a list; later values of a key replace
        earlier ones, including those this scene was given."""
        merged = dict(self._values)
        for key, value in dict(values or {}, **keywords).items():
            merged[key] = override_text(key, value)
        return _make(self.path, self._text, merged)

    def __repr__(self):
        given = "".join(f", {key}={value!r}" for key, value in self._values.items())
        return f"<ffrf.Scene {self.path!r} ({self.name or self.kind}){given}>"


def _make(path, text, values):
    value = _ffrf.make_scene(path, text, list(values.items()), "with_values")
    return Scene(value, text, values)


def load_scene(path, values=None):
    """Loads a scene file (TOML), checked as ``ffrf check`` checks it; ``values`` as ``with_values``.
    Raises SceneError listing every problem."""
    path = str(path)
    text = _ffrf.read_scene_file(path)
    merged = {key: override_text(key, value) for key, value in (values or {}).items()}
    return _make(path, text, merged)


def scene_from_text(text, path="<text>", values=None):
    """A scene from TOML text; ``path`` names it in messages (and BEM files are found beside it)."""
    merged = {key: override_text(key, value) for key, value in (values or {}).items()}
    return _make(str(path), text, merged)


def _scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, str) or hasattr(scene, "__fspath__"):
        return load_scene(scene)
    raise TypeError(f"expected an ffrf.Scene (ffrf.load_scene) or a scene file's path, not {type(scene).__name__}")


def _given(**keywords):
    return {key: value for key, value in keywords.items() if value is not None}


def run(scene, *, boom=None, elements=None, modes=None, static_modes=None, stiffening=None, mode_set=None,
        stress_recovery=None, integrator=None, formulation=None, solver=None, rtol=None, atol=None, duration=None, step=None,
        max_order=None, max_steps=None, max_wall_time=None, min_step=None):
    """Static equilibrium, then the dynamics of one crane model (``ffrf run``). Returns a ``Run``:
    ``time`` and ``outputs[channel]`` as numpy arrays, ``summary`` as ``ffrf run --json``."""
    return Run(_ffrf.run(_scene(scene)._value, _given(
        boom=boom, elements=elements, modes=modes, static_modes=static_modes, stiffening=stiffening, mode_set=mode_set,
        stress_recovery=stress_recovery, integrator=integrator, formulation=formulation, solver=solver, rtol=rtol,
        atol=atol, duration=duration, step=step, max_order=max_order, max_steps=max_steps, max_wall_time=max_wall_time, min_step=min_step)))


def compare(scene, *, tolerance=None, stiffening=None, integrator=None, formulation=None, solver=None, rtol=None,
            atol=None, duration=None, step=None, max_order=None, max_steps=None, max_wall_time=None, min_step=None,
            reference_elements=None, reference_rtol=None, reference_bound=None, reference_levels=None):
    """The boom models against a converged reference, judged at ``tolerance`` (``ffrf compare``).
    Returns a ``Comparison``: ``verdict``, ``models`` (errors, speed-ups), ``summary``."""
    return Comparison(_ffrf.compare(_scene(scene)._value, _given(
        tolerance=tolerance, stiffening=stiffening, integrator=integrator, formulation=formulation, solver=solver,
        rtol=rtol, atol=atol, duration=duration, step=step, max_order=max_order, max_steps=max_steps,
        max_wall_time=max_wall_time, min_step=min_step, reference_elements=reference_elements,
        reference_rtol=reference_rtol, reference_bound=reference_bound, reference_levels=reference_levels)))


def recommend(scene, *, tolerance=None, outputs=None, duration=None, reference_elements=None, reference_rtol=None,
              reference_bound=None, reference_levels=None):
    """The cheapest boom model and integrator within ``tolerance`` (``ffrf recommend``). Returns a
    ``Recommendation``: ``chosen`` (None when no candidate met it), ``decision``, ``summary``."""
    return Recommendation(_ffrf.recommend(_scene(scene)._value, _given(
        tolerance=tolerance, outputs=outputs, duration=duration, reference_elements=reference_elements,
        reference_rtol=reference_rtol, reference_bound=reference_bound, reference_levels=reference_levels)))


def rao(scene, *, periods=None, frequencies=None, boom=None, elements=None, modes=None, static_modes=None,
        stiffening=None, mode_set=None, refine_peaks=None, spectrum=None):
    """RAOs and coupled natural modes of the linearised crane (``ffrf rao``): at wave ``periods`` [s]
    or angular ``frequencies`` [rad/s] (the default grid otherwise); rigid, nodal and modal booms
    unless a model is named. Returns a ``RaoResult``."""
    if periods is not None and frequencies is not None:
        raise TypeError("rao() takes periods or frequencies, not both")
    return RaoResult(_ffrf.rao(_scene(scene)._value, _given(
        periods=periods, frequencies=frequencies, boom=boom, elements=elements, modes=modes, static_modes=static_modes,
        stiffening=stiffening, mode_set=mode_set, refine_peaks=refine_peaks, spectrum=spectrum)))


def modes(scene, *, count=None, elements=None, boundary=None, solver=None):
    """Natural frequencies and mode shapes of the boom against Euler–Bernoulli theory (``ffrf modes``).
    Returns a ``Modes``."""
    try:
        return Modes(_ffrf.modes(_scene(scene)._value, _given(count=count, elements=elements, boundary=boundary,
                                                             solver=solver)))
    except SettingError as error:
        if error.keyword != "modes":
            raise
        raise SettingError(f"count={error.value}: {error.problem}", "count", error.setting, error.value,
                           error.problem) from None


def sweep(scene, *, grid=None, duration=None, jobs=None, tolerance=None, stiffening=None, reference_elements=None,
          reference_rtol=None, reference_bound=None, reference_levels=None):
    """Boom model × integrator × tolerance against a converged reference on ``jobs`` threads
    (``ffrf sweep``; MPI and sharding stay the command line's). Returns a ``Sweep``."""
    return Sweep(_ffrf.sweep(_scene(scene)._value, _given(
        grid=grid, duration=duration, jobs=jobs, tolerance=tolerance, stiffening=stiffening,
        reference_elements=reference_elements, reference_rtol=reference_rtol, reference_bound=reference_bound,
        reference_levels=reference_levels)))


def stability(scene, *, quick=None, out=None):
    """The stability map: where each method fails, each failure named (``ffrf stability``); with
    ``out`` the report, CSVs and charts are written there. Returns a ``Stability``."""
    return Stability(_ffrf.stability(_scene(scene)._value, _given(quick=quick, out=None if out is None else str(out))))


def operability(scene, *, hs, tp, headings=None, seeds=None, duration=None, gamma=None, components=None,
                band_share=None, verify=None, converged_elements=None, tolerance=None, daf_limit=None,
                slack_margin=None, cargo_motion_limit=None, moment_capacity=None, buckling_ratio=None, threads=None,
                journal=None):
    """The operability table over sea states ``hs`` [m] × ``tp`` [s] (× ``headings``) on ``threads``
    (``ffrf operability``; MPI stays the command line's). The journal of finished records goes to
    ``journal`` (a rerun resumes from it) or to a temporary directory removed at the end. Returns an
    ``Operability``."""
    return Operability(_ffrf.operability(_scene(scene)._value, _given(
        hs=hs, tp=tp, headings=headings, seeds=seeds, duration=duration, gamma=gamma, components=components,
        band_share=band_share, verify=verify, converged_elements=converged_elements, tolerance=tolerance,
        daf_limit=daf_limit, slack_margin=slack_margin, cargo_motion_limit=cargo_motion_limit,
        moment_capacity=moment_capacity, buckling_ratio=buckling_ratio, threads=threads,
        journal=None if journal is None else str(journal))))


def baseline_record(scene, *, out=None, outputs=None, boom=None, elements=None, modes=None, static_modes=None,
                    stiffening=None, mode_set=None, integrator=None, formulation=None, solver=None, rtol=None,
                    atol=None, duration=None, step=None, max_order=None):
    """Runs one model and records its regression baseline (``ffrf baseline record``), written to
    ``out`` when given. Returns a ``Baseline`` (``summary``: the file's document)."""
    return Baseline(_ffrf.baseline_record(_scene(scene)._value, _given(
        out=None if out is None else str(out), outputs=outputs, boom=boom, elements=elements, modes=modes,
        static_modes=static_modes, stiffening=stiffening, mode_set=mode_set, integrator=integrator,
        formulation=formulation, solver=solver, rtol=rtol, atol=atol, duration=duration, step=step,
        max_order=max_order)))


def baseline_check(scene, baseline, *, boom=None, elements=None, modes=None, static_modes=None, stiffening=None,
                   mode_set=None, integrator=None, rtol=None, atol=None, duration=None, step=None, max_order=None,
                   response_rtol=None, response_atol=None, frequency_rtol=None, tolerances=None):
    """Runs the baseline's model again (or the one named) and judges every recorded quantity
    (``ffrf baseline check``; ``rtol``/``atol`` are the integrator's, ``response_rtol``/
    ``response_atol``/``frequency_rtol``/``tolerances`` the check's). Returns a ``BaselineCheck``."""
    return BaselineCheck(_ffrf.baseline_check(_scene(scene)._value, str(baseline), _given(
        boom=boom, elements=elements, modes=modes, static_modes=static_modes, stiffening=stiffening,
        mode_set=mode_set, integrator=integrator, rtol=rtol, atol=atol, duration=duration, step=step,
        max_order=max_order, response_rtol=response_rtol, response_atol=response_atol, frequency_rtol=frequency_rtol,
        tolerances=tolerances)))
