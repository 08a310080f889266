"""The kernel's errors: what it raises when an input is outside what an algorithm accepts.

A :class:`KernelError` is the caller's mistake or a documented limit (the language shows it as a
user error with its position); any other exception out of the kernel is a bug (shown as an internal
error).  Raise the most specific subclass; add one here when no existing kind fits."""
from __future__ import annotations


class KernelError(Exception):
    """An input the kernel cannot compute with, or a documented limit it reached."""
