"""docs/PYTHON.md's Python examples run, and print what the page says they print (STYLE.md: every command a
document shows is run by a test)."""
import contextlib
import io
import pathlib
import re

PAGE = pathlib.Path(__file__).resolve().parents[2] / "docs" / "PYTHON.md"


def test_every_python_block_prints_the_text_block_after_it():
    blocks = re.findall(r"```(\w+)\n(.*?)```", PAGE.read_text(), flags=re.S)
    examples = [(code, blocks[i + 1][1] if i + 1 < len(blocks) and blocks[i + 1][0] == "text" else None)
                for i, (language, code) in enumerate(blocks) if language == "python"]
    assert examples, "no Python example on the page"
    for code, expected in examples:
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            exec(compile(code, str(PAGE), "exec"), {})
        if expected is not None:
            assert printed.getvalue() == expected
