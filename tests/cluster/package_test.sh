#!/usr/bin/env bash
# The .deb for the nodes (docs/cluster.md, "A package for the nodes"): `cpack -G DEB` makes it;
# lintian finds no error in it; every library the program links directly comes from a package its
# Depends names (a second look, by objdump and dpkg -S, at what dpkg-shlibdeps found); apt would
# install it on a Debian 12 system holding nothing yet (apt's own resolver against Debian 12's
# package lists, simulated with an empty dpkg status); and dpkg installs it into a throw-away root
# whose `fapc --version` runs. Usage: package_test.sh BUILD_DIR
set -euo pipefail
build=$(realpath "$1")
fail() { echo "package test: $*" >&2; exit 1; }
for program in cpack dpkg-deb dpkg-shlibdeps lintian objdump apt-get; do
  command -v "$program" > /dev/null || fail "$program is missing (README command 2 installs it)"
done
tmp=$(mktemp -d /tmp/fapc-deb-XXXXXX)
trap 'rm -rf "$tmp"' EXIT

(cd "$build" && cpack -G DEB -B "$tmp/out" > "$tmp/cpack.log" 2>&1) || { cat "$tmp/cpack.log" >&2; fail "cpack failed"; }
deb=$(ls "$tmp"/out/fapc_*.deb)
[ -f "$deb" ] || fail "no .deb made"
echo "package test: $(basename "$deb")"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"

# lintian: no error (warnings are reported, not fatal).
lintian --fail-on error --tag-display-limit 0 "$deb" | tee "$tmp/lintian.txt" || fail "lintian found errors"

# What the program needs, from the package's own binary.
mkdir -p "$tmp/x"
dpkg-deb -x "$deb" "$tmp/x"
[ -x "$tmp/x/usr/bin/fapc" ] || fail "no usr/bin/fapc in the package"
for doc in copyright changelog.Debian.gz; do [ -f "$tmp/x/usr/share/doc/fapc/$doc" ] || fail "no $doc"; done
[ -f "$tmp/x/usr/share/man/man1/fapc.1.gz" ] || fail "no manual page"
[ -z "$(find "$tmp/x" -name '*.a' -o -name '*.hpp')" ] || fail "libraries or headers in the program's package"
names=$(echo "$depends" | tr ',' '\n' | sed 's/^ *//; s/ .*//; s/|.*//')
ldconfig -p > "$tmp/ldconfig.txt"  # (read from a file: awk stopping early must not break a pipe)
for library in $(objdump -p "$tmp/x/usr/bin/fapc" | awk '/NEEDED/ {print $2}'); do
  path=$(awk -v l="$library" '$1 == l && /x86-64/ {print $NF; exit}' "$tmp/ldconfig.txt")
  [ -n "$path" ] || fail "$library is not on this machine"
  # dpkg knows a library by the path its package installed (/lib or /usr/lib: merged /usr).
  package=$( (dpkg -S "$(realpath "$path")" 2> /dev/null || dpkg -S "$path") | sed -n '1s/:.*//p')
  echo "$names" | grep -qx "$package" || fail "$library comes from $package, which Depends does not name"
done

# apt on a system with nothing installed yet: the dependencies resolve among Debian 12's packages.
mkdir -p "$tmp/apt"
: > "$tmp/apt/status"
apt-get install --simulate --no-install-recommends -o Dir::State::status="$tmp/apt/status" "$deb" \
  > "$tmp/apt.txt" 2>&1 || { tail -20 "$tmp/apt.txt" >&2; fail "apt cannot install it on an empty Debian 12"; }
grep -q '^Inst fapc ' "$tmp/apt.txt" || fail "apt would not install fapc: $(tail -5 "$tmp/apt.txt")"
echo "package test: apt would install $(grep -c '^Inst ' "$tmp/apt.txt") packages on an empty Debian 12"

# dpkg into a throw-away root (dependencies are the host's: checked above), then the program runs.
root="$tmp/root"
mkdir -p "$root/var/lib/dpkg/info" "$root/var/lib/dpkg/updates" "$root/var/lib/dpkg/triggers"
: > "$root/var/lib/dpkg/status"
dpkg --root="$root" --force-depends --force-script-chrootless --log=/dev/null -i "$deb" > "$tmp/dpkg.txt" 2>&1 ||
  { cat "$tmp/dpkg.txt" >&2; fail "dpkg -i failed"; }
dpkg --root="$root" -s fapc | grep -q '^Status: install ok installed' || fail "dpkg does not list fapc as installed"
version=$("$root/usr/bin/fapc" --version) || fail "the installed fapc does not run"
echo "$version" | grep -q '^fapc 0\.' || fail "unexpected version: $version"
echo "package test: installed, $version"
