"""pip install ./python into a venv that uses Debian's python3-cffi and
python3-numpy, with nothing downloaded (docs/python.md gives the command),
then the installed package renders the CLI's samples."""
import os
import shutil
import subprocess
import sys

from conftest import SOURCE, cli_render, env_path, example, wav_data


def test_pip_install_into_a_venv(tmp_path):
    # a copy, so that setuptools' build/ and egg-info stay out of the source tree
    package = tmp_path / "python"
    shutil.copytree(os.path.join(SOURCE, "python"), package,
                    ignore=shutil.ignore_patterns("tests", "build", "*.egg-info",
                                                  "__pycache__", "CMakeLists.txt"))
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)],
                   check=True)
    pip = subprocess.run([str(venv / "bin" / "pip"), "install", "--no-index",
                          "--no-build-isolation", "--no-deps", str(package)],
                         capture_output=True, text=True)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    build = env_path("FULGUR_BUILD_DIR")
    libs = os.pathsep.join([os.path.join(build, "engine"), os.path.join(build, "host")])
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "FULGUR_LIBRARY_PATH")}
    code = ("import sys, fulgur; s, rate = fulgur.render(sys.argv[1]);"
            "sys.stdout.write(fulgur.__file__ + '\\n'); sys.stdout.flush();"
            "sys.stdout.buffer.write(s.tobytes())")
    scene = example("explicit_tree.json")
    ran = subprocess.run([str(venv / "bin" / "python"), "-c", code, scene], capture_output=True,
                         env=dict(env, FULGUR_LIBRARY_PATH=libs), cwd=tmp_path)
    assert ran.returncode == 0, ran.stderr.decode()
    where, _, samples = ran.stdout.partition(b"\n")
    assert where.decode().startswith(str(venv))  # the installed copy, not the build tree's
    rc, err = cli_render(scene, str(tmp_path / "cli.wav"))
    assert rc == 0, err
    assert samples == wav_data(tmp_path / "cli.wav")[4]
    # without the libraries anywhere it says where to find them
    lost = subprocess.run([str(venv / "bin" / "python"), "-c", "import fulgur"],
                          capture_output=True, text=True, env=env, cwd=tmp_path)
    if lost.returncode != 0:  # (unless they are installed system-wide here)
        assert "FULGUR_LIBRARY_PATH" in lost.stderr and "libfulgur.so.0.1" in lost.stderr
