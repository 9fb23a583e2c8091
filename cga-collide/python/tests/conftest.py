"""Shared fixtures of the cga_collide test suite."""

import pathlib

import numpy as np
import pytest

import cga_collide as cc

HERE = pathlib.Path(__file__).resolve().parent
FIXTURES = HERE / "fixtures"
REPO = HERE.parents[2]


@pytest.fixture(scope="session")
def fixtures() -> pathlib.Path:
    return FIXTURES


def translation(x: float, y: float = 0.0, z: float = 0.0) -> np.ndarray:
    t = np.eye(4)
    t[:3, 3] = (x, y, z)
    return t


def rotation_z(degrees: float, t=(0.0, 0.0, 0.0)) -> np.ndarray:
    return cc.pose_from_degrees([0.0, 0.0, degrees], t)


def random_poses(k: int, seed: int, spread: float = 1.0) -> np.ndarray:
    """k random rigid motions (uniform rotations from normalised quaternions)."""
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(k, 4))
    q /= np.linalg.norm(q, axis=1)[:, None]
    w, x, y, z = q.T
    m = np.zeros((k, 4, 4))
    m[:, 0, 0] = 1 - 2 * (y * y + z * z)
    m[:, 0, 1] = 2 * (x * y - z * w)
    m[:, 0, 2] = 2 * (x * z + y * w)
    m[:, 1, 0] = 2 * (x * y + z * w)
    m[:, 1, 1] = 1 - 2 * (x * x + z * z)
    m[:, 1, 2] = 2 * (y * z - x * w)
    m[:, 2, 0] = 2 * (x * z - y * w)
    m[:, 2, 1] = 2 * (y * z + x * w)
    m[:, 2, 2] = 1 - 2 * (x * x + y * y)
    m[:, :3, 3] = rng.uniform(-spread, spread, size=(k, 3))
    m[:, 3, 3] = 1.0
    return m
