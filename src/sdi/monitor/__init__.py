"""Monitor: does execution follow the plan? δ(Q_plan, Q_exec) ≤ ε (paper Sub-problem 5, §III-E).

`deviation` and `verify_trajectory` judge a recorded run; `StreamingMonitor` judges samples as
they arrive so execution can pause at the first breach; `report` plots and summarises either.
"""

from sdi.monitor.deviation import (
    Breach,
    DeviationResult,
    DeviationSeries,
    MonitorError,
    StreamingMonitor,
    TrajectoryCheck,
    deviation,
    verify_trajectory,
)
from sdi.monitor.report import plot_deviation, report_dict

__all__ = [
    "Breach",
    "DeviationResult",
    "DeviationSeries",
    "MonitorError",
    "StreamingMonitor",
    "TrajectoryCheck",
    "deviation",
    "plot_deviation",
    "report_dict",
    "verify_trajectory",
]
