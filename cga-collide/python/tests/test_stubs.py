"""The type stubs name every public method and property of the extension's classes."""

import ast
import pathlib

import cga_collide as cc

STUB = pathlib.Path(cc.__file__).with_name("__init__.pyi")


def stub_members():
    tree = ast.parse(STUB.read_text())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            out[node.name] = {
                n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))
            }
    return out


def test_stubs_cover_the_extension():
    members = stub_members()
    for cls in (cc.Collider, cc.Scene, cc.Distance, cc.DistanceBatch, cc.ObjectId):
        public = {n for n in dir(cls) if not n.startswith("__")}
        missing = public - members[cls.__name__]
        assert not missing, f"{cls.__name__}: not in the stubs: {sorted(missing)}"
        for name in public:
            assert getattr(cls, name).__doc__, f"{cls.__name__}.{name} has no docstring"
    assert (STUB.parent / "py.typed").exists()
