"""τ_task: pick-and-place steps, robot assignment and the one- or two-arm schedule."""

from sdi.tasks.events import FailureEvent
from sdi.tasks.generator import TaskGenerator, pose_tuple
from sdi.tasks.schedule import Schedule, Slot, list_schedule
from sdi.tasks.task import PickPlace, TaskPlan, Waypoint

__all__ = [
    "FailureEvent",
    "PickPlace",
    "Schedule",
    "Slot",
    "TaskGenerator",
    "TaskPlan",
    "Waypoint",
    "list_schedule",
    "pose_tuple",
]
