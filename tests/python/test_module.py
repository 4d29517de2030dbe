"""The module as a whole: its version is the command line's, and its functions take the documented names."""
import inspect

import dfvn


def test_version_is_the_command_lines(cli):
    assert cli("--version").strip() == f"dfvn-sample {dfvn.__version__}"


def test_functions_take_the_keyword_names_the_readme_documents():
    expected = {
        "field": ["points", "seed", "frequency", "noise", "threads"],
        "trace": ["points", "t", "seed", "frequency", "noise", "integrator", "reprojection", "steps"],
        "sample": ["method", "dim", "grid", "n", "seed", "protocol", "scramble", "radius", "ncandidates"],
        "nn_stats": ["points", "domain_side", "knn"],
        "rdf": ["points", "domain_side", "r_max", "bins", "max_queries", "seed"],
    }
    for name, arguments in expected.items():
        function = getattr(dfvn, name)
        try:  # the Python functions (dfvn.sample)
            signature = list(inspect.signature(function).parameters)
        except ValueError:  # the compiled ones: pybind11's first docstring line, "name(a: type, ...)"
            line = function.__doc__.split("\n")[0]
            assert line.startswith(name + "("), line
            signature = [part.split(":")[0].strip(" *(") for part in line[len(name) + 1:].split(",")]
        for argument in arguments:
            assert argument in signature, f"{name} has no argument '{argument}': {signature}"
        if inspect.isfunction(function):
            for argument in arguments[2:]:
                assert argument in function.__doc__, f"{name}'s docstring does not explain '{argument}'"
