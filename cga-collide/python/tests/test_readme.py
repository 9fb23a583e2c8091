"""The repository README's Python quickstart runs as it is."""

import re

from conftest import REPO


def python_blocks(text: str):
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_readme_quickstart_runs():
    readme = (REPO / "README.md").read_text()
    section = readme[readme.index("## From Python"):]
    blocks = python_blocks(section)
    assert blocks, "the README has no Python quickstart"
    exec(compile(blocks[0], "README.md (Python quickstart)", "exec"), {"__name__": "readme"})


def test_docs_examples_run(tmp_path, monkeypatch):
    """The self-contained examples of docs/python.md (those marked `# runs`) run."""
    text = (REPO / "docs" / "python.md").read_text()
    blocks = [b for b in python_blocks(text) if b.startswith("# runs")]
    assert blocks
    monkeypatch.chdir(tmp_path)
    for k, block in enumerate(blocks):
        exec(compile(block, f"docs/python.md (block {k})", "exec"), {"__name__": "docs"})
