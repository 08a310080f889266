"""Where Python exceptions become the errors the user sees.

mech's own errors (:class:`~mech.dsl.errors.MechError`) pass as they are; the kernel's
(:class:`~mech.kernel.errors.KernelError`: an input outside what an algorithm accepts, or a
documented limit) become runtime errors with the same text, as do division by zero, a recursion
too deep and memory exhausted; any other exception is a bug in mech, shown as an internal error.
"""
from __future__ import annotations

from ..kernel.errors import KernelError
from .errors import MechError, MechInternalError, MechRuntimeError
from .limits import limit_error


def convert_exception(e: BaseException) -> MechError:
    """A Python exception raised during evaluation as the error the user sees (a broken pipe,
    the reader of the output gone as in ``mech f | head``, is raised again for the caller)."""
    if isinstance(e, BrokenPipeError):
        raise e
    if isinstance(e, MechError):
        return e
    if isinstance(e, ZeroDivisionError):
        return MechRuntimeError("division by 0")
    if isinstance(e, RecursionError):
        return MechRuntimeError("recursion too deep")
    if isinstance(e, KernelError):
        return MechRuntimeError(str(e))
    if isinstance(e, MemoryError):
        return limit_error(e)
    if isinstance(e, ArithmeticError):  # exact arithmetic's own (an inverse of 0 mod p, ...)
        return MechRuntimeError(str(e))
    return MechInternalError(f"internal error: {type(e).__name__}: {e}")
