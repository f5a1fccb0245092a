#!/usr/bin/env bash
# After `cmake --install` (make install, make test): makes `python3 -c "import granmix"` work for the python3 first on
# PATH too, when that is not the interpreter the module was built for (a pyenv or virtualenv Python of the same
# version, as on machines that put one first). It writes a .pth file into that interpreter's user site folder naming
# the folder the module went to and Debian's dist-packages (numpy). Appended to sys.path, they never shadow that
# interpreter's own packages. Only prints; never fails the build (exit 0).
set -u
build=${1:-build}
built_for=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' "$build/CMakeCache.txt" 2>/dev/null)
site=$(sed -n 's/^GRANMIX_PYTHON_INSTALL_DIR:PATH=//p' "$build/CMakeCache.txt" 2>/dev/null)
[ -n "$built_for" ] && [ -n "$site" ] || exit 0
command -v python3 > /dev/null || exit 0
if python3 -c "import granmix" > /dev/null 2>&1; then exit 0; fi
want=$("$built_for" -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null)
have=$(python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])' 2>/dev/null)
if [ "$want" != "$have" ]; then
  echo "install: python3 on PATH is Python $have, the module is built for $built_for ($want): use that interpreter, or PYTHONPATH=$build/python with it"
  exit 0
fi
user_site=$(python3 -m site --user-site 2>/dev/null) || exit 0
numpy_dir=$("$built_for" -c 'import numpy, os; print(os.path.dirname(os.path.dirname(numpy.__file__)))' 2>/dev/null)
mkdir -p "$user_site" 2>/dev/null && printf '%s\n' "$site" ${numpy_dir:+"$numpy_dir"} > "$user_site/granmix.pth" 2>/dev/null || exit 0
if python3 -c "import granmix" > /dev/null 2>&1; then
  echo "install: python3 on PATH ($(command -v python3)) finds granmix through $user_site/granmix.pth"
else
  rm -f "$user_site/granmix.pth"
  echo "install: python3 on PATH cannot load the module built for $built_for: use that interpreter"
fi
exit 0
