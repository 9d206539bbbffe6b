"""The README's command examples run as written (outputs redirected to a temporary folder)."""

import re
import shlex

import pytest

from conftest import ROOT, run_cli

BLOCKS = re.findall(r"```bash\n(.*?)```", (ROOT / "README.md").read_text(), re.S)
COMMANDS = [line.split("#")[0].strip() for block in BLOCKS for line in block.splitlines()
            if line.startswith("springscene ")]


def test_readme_opens_with_make_render_and_make_test():
    first = BLOCKS[0]
    assert "make render" in first and "make test" in first


@pytest.mark.parametrize("command", COMMANDS)
def test_readme_command_runs(tmp_path, command):
    args = [a.replace("renders/", f"{tmp_path}/") for a in shlex.split(command)[1:]]
    proc = run_cli(*args)
    assert proc.returncode == 0, proc.stderr
    outs = [a for a in args if a.startswith(str(tmp_path))]
    for out in outs:
        assert (tmp_path / out.split("/")[-1]).stat().st_size > 0
