"""The kernel's errors: what it raises when an input is outside what an algorithm accepts.

A :class:`KernelError` is the caller's mistake or a documented limit (the language shows it as a
user error with its position); any other exception out of the kernel is a bug (shown as an internal
error).  Raise the most specific subclass; add one here when no existing kind fits."""
from __future__ import annotations


class KernelError(Exception):
    """An input the kernel cannot compute with, or a documented limit it reached."""


class DomainError(KernelError):
    """An argument outside the operation's domain: polynomials of another ring, sizes or numbers
    of variables that do not match, a point off the variety, a characteristic that is not a
    prime, a coefficient that cannot be mapped."""


class OrderingError(KernelError):
    """A monomial ordering that is not one, or not of the kind the algorithm needs (global,
    eliminating given variables)."""


class DivisionError(KernelError):
    """An exact division whose divisor does not divide."""


class NotSupported(KernelError):
    """A valid input beyond a documented limit of the algorithm (too large a characteristic,
    no primitive element found, a method that could not verify its result)."""


class EngineError(KernelError):
    """An unknown standard-basis engine, or one that does not accept the ring (its ordering or
    its coefficient field)."""
