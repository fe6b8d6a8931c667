"""The exceptions of ffrf: the command line's errors, with its messages, as Python exceptions.

Every exception ffrf raises for bad input or a failed computation is an ``ffrf.Error``:

* ``SceneError`` (a ``ValueError``): the scene file, or a value given beside it with
  ``Scene.with_values``, has problems; ``problems`` lists each with its file, line, key, value,
  message and origin, as ``ffrf check`` prints them.
* ``SettingError`` (a ``ValueError``): a keyword argument out of its range or not one of its
  choices; ``keyword`` names it, ``value`` and ``problem`` say what is wrong (with the valid range).
* ``SolverFailure`` (a ``RuntimeError``): a solver could not finish; ``kind``, ``time``, ``cause``,
  ``remedy`` and ``adjust`` (the keywords to try) say which, when and what to try.
* ``BaselineFileError`` (a ``ValueError``): a baseline file that cannot be used.

A Ctrl-C during a call raises ``KeyboardInterrupt`` once the computation has stopped.
"""


class Error(Exception):
    """Base class of ffrf's errors."""


class SceneError(Error, ValueError):
    """A scene with problems; ``problems`` is a list of dicts (file, line, column, key, value,
    message, origin, text)."""

    def __init__(self, message, problems=()):
        super().__init__(message)
        self.problems = list(problems)


class SettingError(Error, ValueError):
    """A keyword argument out of its valid range or choices."""

    def __init__(self, message, keyword="", setting="", value="", problem=""):
        super().__init__(message)
        self.keyword = keyword
        self.setting = setting
        self.value = value
        self.problem = problem or message


class SolverFailure(Error, RuntimeError):
    """A solver that could not finish: which failure, when, why, and what to try."""

    def __init__(self, message, kind="", solver="", time=0.0, cause="", remedy="", value=0.0, adjust=""):
        super().__init__(message)
        self.kind = kind
        self.solver = solver
        self.time = time
        self.cause = cause
        self.remedy = remedy
        self.value = value
        self.adjust = adjust


class BaselineFileError(Error, ValueError):
    """A regression baseline file that cannot be used (missing, damaged, another format)."""

    def __init__(self, message, file="", key="", value="", problem=""):
        super().__init__(message)
        self.file = file
        self.key = key
        self.value = value
        self.problem = problem
