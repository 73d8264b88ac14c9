"""Copies of a simulator's mutable state that share what cannot change (the look-ahead's saves)."""

from __future__ import annotations

import dataclasses
import enum
import pickle
import random
from typing import Any

_VALUE, _TUPLE, _LIST, _DICT, _SET, _RNG, _FIELDS, _ARRAY, _PICKLE = range(9)

_KINDS: dict[type, int] = {
    t: _VALUE for t in (int, float, str, bytes, bool, type(None), complex, range, frozenset)
}
_KINDS.update({tuple: _TUPLE, list: _LIST, dict: _DICT, set: _SET})
_FIELD_NAMES: dict[type, tuple[str, ...]] = {}


class _Blob:
    """An object :func:`freeze` cannot copy: pickled, unpickled again by :func:`thaw`."""

    __slots__ = ("data",)

    def __init__(self, data: bytes) -> None:
        self.data = data


def _kind(t: type) -> int:
    k = _KINDS.get(t)
    if k is not None:
        return k
    params = getattr(t, "__dataclass_params__", None)
    if issubclass(t, enum.Enum) or (params is not None and params.frozen):
        k = _VALUE
    elif params is not None and "__slots__" in vars(t):  # (every attribute is a field)
        k = _FIELDS
        _FIELD_NAMES[t] = tuple(f.name for f in dataclasses.fields(t))  # type: ignore[arg-type]
        if set(_FIELD_NAMES[t]) != set(vars(t)["__slots__"]):
            k = _PICKLE
    elif issubclass(t, random.Random):
        k = _RNG
    elif t.__module__ == "numpy" and t.__name__ == "ndarray":
        k = _ARRAY
    else:
        k = _PICKLE
    _KINDS[t] = k
    return k


def _copy(x: Any, memo: dict[int, Any], thaw: bool) -> Any:
    # (values are common leaves: looked up inline, without a call, in every container)
    t: Any = type(x)
    kind = _KINDS.get(t)
    if kind is None:
        kind = _kind(t)
    if kind == _VALUE:
        return x
    if kind == _TUPLE:
        if all(_KINDS.get(type(v)) == _VALUE for v in x):
            return x
        items = [_copy(v, memo, thaw) for v in x]
        return x if all(a is b for a, b in zip(items, x, strict=True)) else tuple(items)
    key = id(x)
    done = memo.get(key)
    if done is not None:
        return done
    out: Any
    kinds = _KINDS
    if kind == _LIST:
        out = memo[key] = []
        out.extend([v if kinds.get(type(v)) == _VALUE else _copy(v, memo, thaw) for v in x])
    elif kind == _DICT:
        out = memo[key] = {
            k: v if kinds.get(type(v)) == _VALUE else _copy(v, memo, thaw) for k, v in x.items()
        }
    elif kind == _SET:
        out = memo[key] = {_copy(v, memo, thaw) for v in x}
    elif kind == _FIELDS:
        out = memo[key] = object.__new__(t)
        for name in _FIELD_NAMES[t]:
            v = getattr(x, name)
            if kinds.get(type(v)) != _VALUE:
                v = _copy(v, memo, thaw)
            object.__setattr__(out, name, v)
    elif kind == _RNG:
        out = memo[key] = t.__new__(t)
        out.setstate(x.getstate())
    elif kind == _ARRAY:
        out = memo[key] = x.copy()
    elif thaw and t is _Blob:
        out = memo[key] = pickle.loads(x.data)
    elif t is _Blob:  # (a blob in a snapshot is shared by every restore)
        out = memo[key] = x
    else:
        out = memo[key] = _Blob(pickle.dumps(x, protocol=pickle.HIGHEST_PROTOCOL))
    return out


def freeze(state: dict[str, Any]) -> dict[str, Any]:
    """A copy of ``state`` that later changes to it do not reach (see the module's docstring)."""
    out: dict[str, Any] = _copy(state, {}, False)
    return out


def thaw(snapshot: dict[str, Any]) -> dict[str, Any]:
    """A fresh copy of what :func:`freeze` returned (the snapshot stays as it was, so it can
    be thawed again)."""
    out: dict[str, Any] = _copy(snapshot, {}, True)
    return out
