"""Robot programs for verified plans: ABB RAPID modules and abb-motion-program-exec scripts."""

from sdi.export.interlocks import InterlockPlan, interlock_plan
from sdi.export.python_program import python_program
from sdi.export.rapid import confdata, rapid_module

__all__ = ["InterlockPlan", "confdata", "interlock_plan", "python_program", "rapid_module"]
