"""The type stubs (cellproj/__init__.pyi) against the module: every public name declared, and every
function's and method's parameters, in order, as the module has them."""
import ast
import inspect
import os
import re

import cellproj

STUB = os.path.join(os.path.dirname(cellproj.__file__), "__init__.pyi")


def stub_tree():
    with open(STUB) as f:
        return ast.parse(f.read())


def parameters(function):
    """A function's parameter names in order: by inspect for Python's, from the signature pybind11
    writes in the docstring's first line for the module's own."""
    try:
        return [p for p in inspect.signature(function).parameters if p != "self"]
    except (TypeError, ValueError):
        line = function.__doc__.strip().split("\n")[0]
        inside = line[line.index("(") + 1:line.rindex(")")]
        names = re.findall(r"(?:^|, )\**(\w+)(?=:|$|,)", inside)
        return [n for n in names if n != "self"]


def stub_parameters(node):
    a = node.args
    names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
    if a.kwarg:
        names.append(a.kwarg.arg)
    return [n for n in names if n not in ("self", "cls")]


def test_every_public_name_is_in_the_stubs():
    declared = {n.name for n in stub_tree().body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert set(cellproj.__all__) <= declared, set(cellproj.__all__) - declared


def test_the_stubs_parameters_are_the_modules():
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            runtime = [p for p in parameters(getattr(cellproj, node.name)) if p not in ("kwargs", "settings")]
            assert runtime == [p for p in stub_parameters(node) if p not in ("kwargs", "settings")], node.name
        if isinstance(node, ast.ClassDef) and not node.name.endswith("Error"):
            cls = getattr(cellproj, node.name)
            public = {a for a in dir(cls) if not a.startswith("_")} - set(dir(__import__("numpy").ndarray))
            in_stub = {m.name for m in node.body if isinstance(m, ast.FunctionDef)}
            in_stub |= {m.target.id for m in node.body if isinstance(m, ast.AnnAssign)}
            assert public <= in_stub, (node.name, public - in_stub)
            for m in node.body:
                if isinstance(m, ast.FunctionDef) and not m.decorator_list and m.name in ("save", "add", "orbit",
                                                                                            "field", "add_field"):
                    assert parameters(getattr(cls, m.name)) == stub_parameters(m), (node.name, m.name)
