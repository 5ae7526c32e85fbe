"""python/saltus.pyi tells editors what the module holds: the same names, the same parameters."""

import ast
import inspect
import pydoc
from pathlib import Path

import saltus

STUB = Path(saltus.__file__).with_name("saltus.pyi")


def public(names):
    return {n for n in names if not n.startswith("_")}


def stub_tree():
    return ast.parse(STUB.read_text())


def stub_parameters(function):
    a = function.args
    return ([p.arg for p in a.posonlyargs + a.args if p.arg != "self"],
            [p.arg for p in a.kwonlyargs])


def module_parameters(function):
    signature = inspect.signature(function)
    positional = [p.name for p in signature.parameters.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) and p.name != "self"]
    keyword = [p.name for p in signature.parameters.values() if p.kind == p.KEYWORD_ONLY]
    return positional, keyword


def test_the_stub_lies_beside_the_module():
    assert STUB.is_file(), STUB


def test_the_stub_names_every_public_name_of_the_module_and_no_other():
    declared = set()
    for node in stub_tree().body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            declared.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            declared.add(node.target.id)
    helpers = {"Array", "PathLike", "ModelLike", "MotionLike"}  # the stub's own type aliases
    assert public(declared) - helpers == public(dir(saltus)) - {"annotations"}


def test_each_function_takes_the_parameters_the_stub_gives_it():
    for node in stub_tree().body:
        if isinstance(node, ast.FunctionDef):
            assert stub_parameters(node) == module_parameters(getattr(saltus, node.name)), node.name


def test_each_class_has_the_members_the_stub_gives_it():
    for node in stub_tree().body:
        if not isinstance(node, ast.ClassDef) or node.name in ("InputError", "OutputError"):
            continue
        cls = getattr(saltus, node.name)
        members = set()
        for item in node.body:
            if isinstance(item, ast.FunctionDef):
                members.add(item.name)
                if item.name != "__init__" and not item.name.startswith("__"):
                    if not any(isinstance(d, ast.Name) and d.id == "property"
                               for d in item.decorator_list):
                        assert stub_parameters(item) == module_parameters(
                            getattr(cls, item.name)), (node.name, item.name)
            elif isinstance(item, ast.AnnAssign):
                members.add(item.target.id)
        own = public(vars(cls))
        assert public(members) == own, (node.name, public(members) ^ own)
    assert public(vars(saltus.Evaluation)) >= {"average_root_force", "result", "write"}


def test_the_errors_are_value_and_os_errors():
    assert issubclass(saltus.InputError, ValueError)
    assert issubclass(saltus.OutputError, OSError)


def test_optimize_takes_every_option_of_the_table_by_the_cli_s_name():
    table = saltus.option_table()
    keywords = [o["keyword"] for o in table]
    # The CLI's flag in snake case: --max-iter is max_iter, --no-timing is no_timing.
    assert keywords == [o["flag"][2:].replace("-", "_") for o in table]
    _, optimize_keywords = module_parameters(saltus.optimize)
    assert optimize_keywords == ["progress"] + keywords
    _, evaluate_keywords = module_parameters(saltus.evaluate)
    assert evaluate_keywords == [o["keyword"] for o in table if o["evaluation"]]
    parameters = inspect.signature(saltus.optimize).parameters
    for option in table:
        assert parameters[option["keyword"]].default == option["default"], option["keyword"]
    for option in table:
        if option["evaluation"]:
            default = inspect.signature(saltus.evaluate).parameters[option["keyword"]].default
            assert default == option["evaluation_default"], option["keyword"]


def test_the_defaults_are_the_cli_s():
    """optimize --help prints each flag's default: the module's signature has the same."""
    import re
    from conftest import run_cli
    help_text = run_cli("optimize", "--help").stdout
    parameters = inspect.signature(saltus.optimize).parameters
    for option in saltus.option_table():
        default = parameters[option["keyword"]].default
        if option["type"] == "bool":
            assert default is False  # the flag is not given
            continue
        printed = re.search(re.escape(option["flag"]) + r" \S+=(\S+)", help_text).group(1)
        if isinstance(default, str):
            assert printed == default, option["keyword"]
        else:
            assert float(printed) == default, option["keyword"]


def test_help_lists_every_option_with_its_help():
    text = pydoc.render_doc(saltus.optimize, renderer=pydoc.plaintext)
    for option in saltus.option_table():
        assert option["keyword"] + " :" in text, option["keyword"]
    assert "Ipopt's iteration limit" in text
    assert "progress" in text
