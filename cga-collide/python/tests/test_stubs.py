"""The type stubs carry the extension's docstrings, word for word, so an editor shows what
`help()` shows. (CI runs mypy's stubtest, which holds the stubs' names and signatures to the
extension.)"""

import ast
import inspect
import pathlib
import types

import pytest

import cga_collide as cc
from cga_collide import motion

STUBS = {
    cc: pathlib.Path(cc.__file__).with_name("__init__.pyi"),
    motion: pathlib.Path(motion.__file__).with_name("motion.pyi"),
}


def stub_docs(path: pathlib.Path):
    """(qualified name, docstring) of every class, function and method of a stub file."""
    out = []

    def visit(body, prefix):
        for node in body:
            if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
                out.append((prefix + node.name, ast.get_docstring(node)))
                if isinstance(node, ast.ClassDef):
                    visit(node.body, prefix + node.name + ".")

    visit(ast.parse(path.read_text()).body, "")
    return out


def runtime(module: types.ModuleType, qualname: str):
    obj = module
    for part in qualname.split("."):
        obj = getattr(obj, part)
    return obj


def documented():
    """Every stub entry whose runtime object has a docstring of its own (not the generic text
    of a Python slot such as ``__len__`` or the constructor)."""
    for module, path in STUBS.items():
        for name, doc in stub_docs(path):
            if name.rpartition(".")[2].startswith("__"):
                continue
            yield pytest.param(module, name, doc, id=f"{module.__name__}.{name}")


@pytest.mark.parametrize("module, name, stub_doc", list(documented()))
def test_stub_carries_the_runtime_docstring(module, name, stub_doc):
    doc = runtime(module, name).__doc__
    assert doc, f"{name} has no docstring at runtime"
    assert stub_doc == inspect.cleandoc(doc), f"{name}: the stub's docstring differs from the extension's"


def test_every_public_name_has_a_documented_stub():
    for module, path in STUBS.items():
        names = {n for n, _ in stub_docs(path)}
        for name in module.__all__:
            obj = getattr(module, name)
            if isinstance(obj, (type, types.BuiltinFunctionType)):
                assert name in names, f"{module.__name__}.{name} is not in {path.name}"
    assert (STUBS[cc].parent / "py.typed").exists()
