"""Parts of a model made when first read, not when the model is built.

A chain of n links has points P_k = P_{k−1} + l (sin θ_k, −cos θ_k): written out in
sympy, P_k is a sum of k terms, and sympy keeps each sum sorted, so building the n
points costs Σ k ≈ n²/2 comparisons of terms (a 200-link chain: most of a second). The
floating-point route never reads them (it evaluates the problem's own expression trees,
:mod:`rbdsolve.model.numeric.numeric`), so they are folded on first read:

- ``Later(make)``: a value to be made by ``make()`` when first read.
- ``Deferred``: a dataclass field that also accepts a Later; the first read makes the
  value and keeps it, so the field reads as an ordinary value (``replace`` and ``==``
  read it too).
- ``Points``: the named points, each folded on first read, with every point before it
  in the file's dependency order (so that folding P_200 never recurses through the
  199 points it names). ``in`` asks for a name without folding it.

What a fold checks (a point that is not a real number, ``Symbols.vector``) is then
reported when the point is first read.
"""

from __future__ import annotations

from typing import Callable, Iterator, Mapping


class Later:
    """A value made by ``make()`` on first read (see Deferred)."""

    __slots__ = ("make",)

    def __init__(self, make: Callable[[], object]):
        self.make = make


class Deferred:
    """A field of a frozen dataclass whose value may be given as a Later: it is made on
    the first read and kept. On the class it has no default (a required field)."""

    def __set_name__(self, owner, name: str) -> None:
        self.slot = "_deferred_" + name

    def __get__(self, obj, owner=None):
        if obj is None:
            raise AttributeError(self.slot)  # for dataclasses: the field has no default
        value = obj.__dict__[self.slot]
        if isinstance(value, Later):
            value = value.make()
            obj.__dict__[self.slot] = value
        return value

    def __set__(self, obj, value) -> None:
        obj.__dict__[self.slot] = value

    @staticmethod
    def made(obj, name: str) -> bool:
        """Has the field ``name`` of ``obj`` a value already (given, or made)?"""
        return not isinstance(obj.__dict__["_deferred_" + name], Later)


class Points(Mapping):
    """Points by name, in dependency order, each made by ``fold(name)`` on first read
    together with the points before it that are not made yet."""

    def __init__(self, names: tuple[str, ...], fold: Callable[[str], object]):
        self._order = {name: i for i, name in enumerate(names)}
        self._names = names
        self._fold = fold
        self._made: dict[str, object] = {}

    def __getitem__(self, name: str):
        if name not in self._made:
            if name not in self._order:
                raise KeyError(name)
            for earlier in self._names[len(self._made):self._order[name] + 1]:
                self._made[earlier] = self._fold(earlier)
        return self._made[name]

    def __contains__(self, name: object) -> bool:
        return name in self._order

    def __iter__(self) -> Iterator[str]:
        return iter(self._names)

    def __len__(self) -> int:
        return len(self._names)
