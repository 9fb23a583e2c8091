"""The type stubs name every public method and property of the extension's classes, and every
function of `cga_collide.motion`."""

import ast
import pathlib

import cga_collide as cc
from cga_collide import motion

STUB = pathlib.Path(cc.__file__).with_name("__init__.pyi")
MOTION_STUB = pathlib.Path(motion.__file__).with_name("motion.pyi")


def stub_members(path: pathlib.Path):
    tree = ast.parse(path.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {
                n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))
            }
        elif isinstance(node, ast.FunctionDef):
            out.setdefault("", set()).add(node.name)
    return out


def check_classes(members, classes):
    for cls in classes:
        public = {n for n in dir(cls) if not n.startswith("__")}
        missing = public - members[cls.__name__]
        assert not missing, f"{cls.__name__}: not in the stubs: {sorted(missing)}"
        for name in public:
            assert getattr(cls, name).__doc__, f"{cls.__name__}.{name} has no docstring"
        assert cls.__doc__, f"{cls.__name__} has no docstring"


def test_stubs_cover_the_extension():
    check_classes(stub_members(STUB), (cc.Collider, cc.Scene, cc.Distance, cc.DistanceBatch, cc.ObjectId))
    assert (STUB.parent / "py.typed").exists()


def test_stubs_cover_motion():
    members = stub_members(MOTION_STUB)
    check_classes(members, (motion.ContactTime, motion.MotionContacts, motion.StepContacts))
    functions = {n for n in motion.__all__ if callable(getattr(motion, n)) and not isinstance(getattr(motion, n), type)}
    assert functions and functions <= members[""], sorted(functions - members[""])
    assert set(motion.__all__) == {n for n in dir(motion) if not n.startswith("_")}
    for name in functions:
        assert getattr(motion, name).__doc__, f"motion.{name} has no docstring"
    assert "contacts_during" in stub_members(STUB)["Collider"]
