#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Lists tracked source files without an SPDX licence line in their first five lines; exit 1
# when there is one. With --fix, inserts the line ("// " for C++, "# " for CMake and shell,
# after a shebang) instead.
set -euo pipefail
cd "$(dirname "$0")/.."
tag='SPDX-License-Identifier: GPL-3.0-or-later'
fix=0
[ "${1:-}" = "--fix" ] && fix=1
missing=0
while IFS= read -r f; do
  head -n 5 "$f" | grep -q 'SPDX-License-Identifier:' && continue
  if [ $fix -eq 0 ]; then
    echo "$f"
    missing=1
    continue
  fi
  case "$f" in
    *.cpp|*.h) printf '// %s\n' "$tag" | cat - "$f" > "$f.spdx" ;;
    *)
      if head -n 1 "$f" | grep -q '^#!'; then
        { head -n 1 "$f"; printf '# %s\n' "$tag"; tail -n +2 "$f"; } > "$f.spdx"
      else
        printf '# %s\n' "$tag" | cat - "$f" > "$f.spdx"
      fi ;;
  esac
  chmod --reference="$f" "$f.spdx"
  mv "$f.spdx" "$f"
done < <(git ls-files -- '*.cpp' '*.h' '*.sh' '*.py' '*.pyi' 'CMakeLists.txt' '*/CMakeLists.txt' '.ci/run')
exit $missing
