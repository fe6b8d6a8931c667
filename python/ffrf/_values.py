"""Scene values given from Python, written as on the command line (``--set KEY=VALUE``).

A value is handed to the scene loader as text, exactly as ``--set`` hands it: the loader reads it
as a TOML value when it is one and as a string otherwise, and checks it as the file's own value.
"""

import json
import math
import numbers


def override_text(key, value):
    """The ``--set`` text of one value: ``"55 deg"`` as given, ``16`` as ``"16"``, ``2.4e6`` as
    ``"2400000.0"``, ``True`` as ``"true"``, a list as a TOML array."""
    if isinstance(value, str):
        return value
    if hasattr(value, "tolist"):  # a numpy scalar or array
        value = value.tolist()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        number = float(value)
        if math.isnan(number):
            return "nan"
        if math.isinf(number):
            return "inf" if number > 0 else "-inf"
        return repr(number)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(json.dumps(item) if isinstance(item, str) else override_text(key, item) for item in value) + "]"
    raise TypeError(f"{key}: a scene value is a str (\"55 deg\"), a number, a bool or a list, not {type(value).__name__}")
