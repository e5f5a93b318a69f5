# SPDX-License-Identifier: GPL-3.0-or-later
"""How the public functions check what they are given, before the engine sees it.

A public function is wrapped by :func:`public`: its own signature is bound first, so a misspelt
keyword is named with the function it was given to (and the keyword it probably meant), a list
where one number belongs is a TypeError naming the function and the keyword (not pybind11's
overload listing of ``kinstab._core``), and a file that does not exist is a FileNotFoundError
naming both. The checks read the annotations as written (``from __future__ import
annotations``: strings), so the signature that help() shows is the one that is checked.
"""

from __future__ import annotations

import difflib
import errno
import functools
import inspect
import numbers
import os
import re
from typing import Any, Callable, TypeVar

import numpy as np

F = TypeVar("F", bound=Callable[..., Any])

_NUMBER = {"float", "Optional[float]"}
_INTEGER = {"int", "Optional[int]"}
_TEXT = {"str", "Optional[str]"}
_FLAG = {"bool"}
_FILE = {"PathLike", "Optional[PathLike]"}  # a file read: it must exist
_OUTPUT = {"OutputPath"}  # a file written


class Default:
    """A default the caller did not override: shown as its value by help(), told apart from the
    same value given on purpose (``simulate(..., case=c, mu=0.6)`` is refused, not ignored)."""

    __slots__ = ("value",)

    def __init__(self, value: Any) -> None:
        self.value = value

    def __repr__(self) -> str:
        return repr(self.value)


def _kind(v: Any) -> str:
    return type(v).__name__


def _is_number(v: Any) -> bool:
    return isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))


def _is_integer(v: Any) -> bool:
    return isinstance(v, numbers.Integral) and not isinstance(v, (bool, np.bool_))


def _check(function: str, name: str, annotation: str, v: Any) -> None:
    if isinstance(v, Default) or (v is None and annotation.startswith("Optional[")):
        return
    if annotation in _NUMBER and not _is_number(v):
        hint = ""
        if isinstance(v, (list, tuple, np.ndarray)):
            hint = "; one value here (surface() and critical() take sequences)"
        raise TypeError(f"{function}(): {name}={v!r} is not a number (a {_kind(v)}){hint}")
    if annotation in _INTEGER and not _is_integer(v):
        raise TypeError(f"{function}(): {name}={v!r} is not a whole number (a {_kind(v)})")
    if annotation in _TEXT and not isinstance(v, str):
        raise TypeError(f"{function}(): {name}={v!r} is not text (a {_kind(v)})")
    if annotation in _FLAG and not isinstance(v, (bool, np.bool_)):
        raise TypeError(f"{function}(): {name}={v!r} is not True or False (a {_kind(v)})")
    if annotation in _OUTPUT and not isinstance(v, (str, os.PathLike)):
        raise TypeError(f"{function}(): {name}={v!r} is not a file name (a {_kind(v)})")
    if annotation in _FILE:
        if not isinstance(v, (str, os.PathLike)):
            raise TypeError(f"{function}(): {name}={v!r} is not a file name (a {_kind(v)})")
        if "\0" in os.fspath(v):  # cut there, it could name a file that exists (issue 31)
            raise ValueError(f"{function}(): {name}={os.fspath(v)!r}: a file name cannot hold "
                             "a NUL character")
        if not os.path.exists(v):
            raise FileNotFoundError(errno.ENOENT, f"{function}(): {name}: no such file",
                                    os.fspath(v))


def _binding_error(function: str, sig: inspect.Signature, e: TypeError) -> TypeError:
    text = str(e)
    m = re.search(r"unexpected keyword argument '(\w+)'", text)
    if m:
        names = [n for n, p in sig.parameters.items() if p.kind != p.VAR_KEYWORD]
        close = difflib.get_close_matches(m.group(1), names, n=1)
        hint = f" (did you mean '{close[0]}'?)" if close else ""
        return TypeError(f"{function}() got an unexpected keyword argument "
                         f"'{m.group(1)}'{hint}")
    return TypeError(f"{function}(): {text}")


def public(f: F) -> F:
    """Runs f; when the call goes wrong, says how in f's own terms.

    The happy path costs one extra call (``simulate`` is called in loops): the arguments are
    checked up front only for a function that reads files (a missing file is then
    FileNotFoundError before the engine's "cannot open"); otherwise only when f raises
    TypeError, which Python's binding (a misspelt keyword) or the engine's (a list where a number
    belongs) gives, the arguments are checked against the annotations to name the one at fault.
    """
    sig = inspect.signature(f)
    name = f.__qualname__
    checked = {n: p.annotation for n, p in sig.parameters.items()
               if isinstance(p.annotation, str)}
    reads_files = any(a in _FILE for a in checked.values())

    def check_all(args: Any, kwargs: Any) -> None:
        try:
            bound = sig.bind(*args, **kwargs)
        except TypeError as e:
            raise _binding_error(name, sig, e) from None
        for arg, v in bound.arguments.items():
            if arg in checked:
                _check(name, arg, checked[arg], v)

    @functools.wraps(f)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        if reads_files:
            check_all(args, kwargs)
        try:
            return f(*args, **kwargs)
        except TypeError as e:
            error = e
        check_all(args, kwargs)  # raises the named error when an argument is at fault
        raise error

    return wrapper  # type: ignore[return-value]


def existing_file(function: str, name: str, path: Any) -> str:
    """path as text, when it names a file; else FileNotFoundError naming function and keyword."""
    _check(function, name, "PathLike", path)
    return os.fspath(path)
