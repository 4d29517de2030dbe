"""The module as a whole: its version is the command line's, and its functions take the documented names."""
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
        signature = getattr(dfvn, name).__doc__.split("\n")[0]
        assert signature.startswith(name + "("), signature
        for argument in arguments:
            assert f"{argument}:" in signature, f"{name} has no argument '{argument}': {signature}"
