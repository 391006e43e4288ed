"""For the project's Python scripts: run a script inside a virtual environment that holds the pip
packages it needs (the python3 on PATH may be a pyenv or system interpreter without them). The
environment is created and filled on first use, then the script is started again with its
interpreter and the same arguments. Scripts started together wait for one another (a lock file
beside the environment), so that one creates and fills it and the others find it done."""
import fcntl
import os
import subprocess
import sys


def reexec_in_venv(tool, venv, packages, modules, script):
    """Returns where `modules` import; else creates `venv` if needed, pip-installs `packages` into
    it if they are missing there, and re-executes `script` with the venv's interpreter."""
    try:
        for m in modules:
            __import__(m)
        return
    except ImportError:
        pass
    py = os.path.join(venv, "bin", "python3")
    if os.environ.get("GDR_VENV_REEXEC") == venv:
        sys.exit(f"{tool}: {', '.join(modules)} still missing in {venv}")
    os.makedirs(os.path.dirname(os.path.abspath(venv)), exist_ok=True)
    with open(os.path.abspath(venv) + ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not os.path.exists(py):
            print(f"{tool}: creating {venv}", file=sys.stderr)
            subprocess.run([sys.executable, "-m", "venv", venv], check=True)
        if subprocess.run([py, "-c", "import " + ", ".join(modules)], capture_output=True).returncode != 0:
            print(f"{tool}: installing {' '.join(packages)} into {venv}", file=sys.stderr)
            subprocess.run([py, "-m", "pip", "install", "--quiet", *packages], check=True)
    os.environ["GDR_VENV_REEXEC"] = venv
    os.execv(py, [py, os.path.abspath(script)] + sys.argv[1:])
