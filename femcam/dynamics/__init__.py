"""Follower-train dynamics: lumped 1-DOF / 2-DOF trains, periodic steady state with contact loss
(free flight and re-impact), jump speed and rpm sweeps. See docs/dynamics.md."""

from .arm import arm_follower, arm_train, lever_spring, rigid_jump_speed
from .jump import JumpResult, RpmSweep, jump_speed, rpm_sweep
from .model import TrainModel, check_resolution
from .periodic import DynamicsResult, periodic_response, simulate

__all__ = ["TrainModel", "check_resolution", "DynamicsResult", "periodic_response", "simulate",
           "JumpResult", "RpmSweep", "jump_speed", "rpm_sweep",
           "arm_follower", "arm_train", "lever_spring", "rigid_jump_speed"]
