"""Where the Python module goes under an install prefix: the directory this interpreter
itself searches under that prefix, relative to it (Debian: /usr -> lib/python3/dist-packages,
/usr/local -> lib/python3.11/dist-packages); for any other prefix, the interpreter's versioned
form (lib/python3.11/dist-packages on Debian, lib/python3.11/site-packages elsewhere), which
PYTHONPATH then names. Prints the relative path. Usage: python3 python_site_dir.py PREFIX"""
import os
import site
import sys

prefix = os.path.abspath(sys.argv[1])
searched = [p for p in site.getsitepackages() + sys.path if p]
for path in searched:
    relative = os.path.relpath(os.path.abspath(path), prefix)
    if relative.startswith("lib") and relative.endswith("-packages"):
        print(relative)
        sys.exit(0)
kind = "dist-packages" if any(p.endswith("dist-packages") for p in searched) else "site-packages"
print(f"lib/python{sys.version_info.major}.{sys.version_info.minor}/{kind}")
