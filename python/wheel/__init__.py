"""The Python module dtwin (docs/python.md), as its wheel installs it: the compiled module is
dtwin/dtwin.<ext>.so beside this file, and importing the package gives that module itself (its
functions, classes, errors and __version__, as PYTHONPATH=build/python gives them); the types are in
__init__.pyi (py.typed), the default study in data/, the licences in licenses/."""
import sys as _sys

from . import dtwin as _module

# The classes and errors are named as the module built in the source tree names them (dtwin.X).
for _value in vars(_module).values():
    if isinstance(_value, type) and getattr(_value, "__module__", None) == _module.__name__:
        try:
            _value.__module__ = __name__
        except (AttributeError, TypeError):
            pass
_sys.modules[__name__] = _module
