"""python/dtwin.pyi and the module agree: every public name of the module is in the stub and every
name of the stub in the module, and each function and method has the same parameters (names,
kinds, defaults) in both. The stub is the one beside the built module (build/python/dtwin.pyi)."""
import ast
import builtins
import inspect
import os
import unittest

import dtwin
from dtwin_testing import SOURCE_DIR

STUB = os.path.join(os.path.dirname(dtwin.__file__), "dtwin.pyi")


def public(names):
    return {n for n in names if not n.startswith("_") or n == "__version__"}


def stub_parameters(fn):
    """[(name, kind, default)] of a stub's def, as inspect names them (ast.literal_eval'd defaults)."""
    a = fn.args
    out = []
    positional = a.posonlyargs + a.args
    defaults = [inspect.Parameter.empty] * (len(positional) - len(a.defaults)) + [ast.literal_eval(d) for d in a.defaults]
    for arg, default in zip(positional, defaults):
        out.append((arg.arg, inspect.Parameter.POSITIONAL_OR_KEYWORD, default))
    for arg, default in zip(a.kwonlyargs, a.kw_defaults):
        out.append((arg.arg, inspect.Parameter.KEYWORD_ONLY, inspect.Parameter.empty if default is None else ast.literal_eval(default)))
    return out


def runtime_parameters(fn):
    return [(p.name, p.kind, p.default) for p in inspect.signature(fn).parameters.values()]


class Stub(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(STUB) as f:
            cls.text = f.read()
        cls.tree = ast.parse(cls.text)
        with open(os.path.join(SOURCE_DIR, "python", "dtwin.pyi")) as f:
            cls.source = f.read()

    def top_level(self):
        names, defs, classes = set(), {}, {}
        for node in self.tree.body:
            if isinstance(node, ast.FunctionDef):
                names.add(node.name)
                defs[node.name] = node
            elif isinstance(node, ast.ClassDef):
                names.add(node.name)
                classes[node.name] = node
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                names.add(node.target.id)
        return public(names), defs, classes

    def test_the_built_stub_is_the_source_stub(self):
        self.assertEqual(self.text, self.source)

    def test_the_same_names(self):
        names, _, classes = self.top_level()
        self.assertEqual(names, public(dir(dtwin)))
        for cls_name, node in classes.items():
            stub_members = public(n.name for n in node.body if isinstance(n, ast.FunctionDef))
            self.assertEqual(stub_members, public(vars(getattr(dtwin, cls_name))), cls_name)

    def test_the_same_signatures(self):
        _, defs, classes = self.top_level()
        checked = 0
        for name, fn in defs.items():
            self.assertEqual(stub_parameters(fn), runtime_parameters(getattr(dtwin, name)), name)
            checked += 1
        for cls_name, node in classes.items():
            runtime_class = getattr(dtwin, cls_name)
            for fn in node.body:
                if not isinstance(fn, ast.FunctionDef) or any(isinstance(d, ast.Name) and d.id == "property" for d in fn.decorator_list):
                    continue
                runtime = inspect.signature(runtime_class) if fn.name == "__init__" else None
                if runtime is not None:  # the class's call: __init__ without self
                    expected = [(p.name, p.kind, p.default) for p in runtime.parameters.values()]
                    self.assertEqual(stub_parameters(fn)[1:], expected, cls_name + ".__init__")
                else:  # self: positional-only in the module's text signature
                    runtime = runtime_parameters(getattr(runtime_class, fn.name))
                    self.assertEqual(runtime[0][:2], ("self", inspect.Parameter.POSITIONAL_ONLY), f"{cls_name}.{fn.name}")
                    self.assertEqual(stub_parameters(fn)[1:], runtime[1:], f"{cls_name}.{fn.name}")
                checked += 1
        self.assertGreaterEqual(checked, 7)

    def test_properties_are_properties(self):
        _, _, classes = self.top_level()
        for fn in classes["Study"].body:
            if isinstance(fn, ast.FunctionDef) and fn.decorator_list:
                self.assertIsInstance(vars(dtwin.Study)[fn.name], property, fn.name)

    def test_exception_bases(self):
        _, _, classes = self.top_level()
        for name, node in classes.items():
            if not node.bases:
                continue
            self.assertTrue(issubclass(getattr(dtwin, name), getattr(builtins, node.bases[0].id)), name)


if __name__ == "__main__":
    unittest.main()
