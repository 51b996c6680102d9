"""Motion: joint trajectories (Q_plan, Q_exec), planning and time parameterisation."""

from sdi.motion.trajectory import JointTrajectory

__all__ = ["JointTrajectory"]
