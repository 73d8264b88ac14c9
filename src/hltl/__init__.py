"""hltl: natural-language instructions to makespan-optimal multi-robot handover plans via H-LTLf."""

from hltl.errors import HltlError

__version__ = "0.1.0"

__all__ = ["HltlError", "__version__"]
