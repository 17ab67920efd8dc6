#!/usr/bin/env bash
# The Windows binary, built with MinGW-w64 and run under Wine: the README's
# main command, standard input, a rewrite in place with its backup, a path
# with a drive letter, and the command-line tests (tests/cli.rs,
# tests/files.rs) with the binary they run.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v x86_64-w64-mingw32-gcc >/dev/null 2>&1 || ! command -v wine >/dev/null 2>&1; then
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq gcc-mingw-w64-x86-64 wine64 >/dev/null
fi
target=x86_64-pc-windows-gnu
if ! rustup target list --installed | grep -qx "$target"; then
  rustup target add "$target"
fi
# One release build: the command-line tests' (tests/cli.rs, tests/files.rs),
# whose binary is also the one run by hand below. A separate `cargo build`
# would compile the crate and half its dependencies a second time (the test
# build's dev-dependencies unify other features), about 3.5 minutes.
cargo test --release --locked --target "$target" --test cli --test files --no-run
out="target/$target/release"
x86_64-w64-mingw32-gcc -shared -o "$out/bcryptprimitives.dll" .ci/bcryptprimitives.c -ladvapi32

export WINEDEBUG=-all
WINEPREFIX="$(mktemp -d)"
export WINEPREFIX
scratch="$(mktemp -d)"
trap 'wineserver -k >/dev/null 2>&1 || true; rm -rf "$WINEPREFIX" "$scratch"' EXIT

wine "$out/sinuprep.exe" rewrite samples/PAPER_EXAMPLE3.MPF > "$scratch/stdout.mpf"
grep -q '_CYC600_2=37.792346' "$scratch/stdout.mpf"
wine "$out/sinuprep.exe" rewrite - < samples/PAPER_EXAMPLE3.MPF > "$scratch/stdin.mpf"
cmp "$scratch/stdout.mpf" "$scratch/stdin.mpf"

cp samples/PAPER_EXAMPLE3.MPF samples/HEAD_DEF.SPF "$scratch/"
wine "$out/sinuprep.exe" rewrite --in-place "Z:${scratch//\//\\}\\PAPER_EXAMPLE3.MPF"
cmp "$scratch/stdout.mpf" "$scratch/PAPER_EXAMPLE3.MPF"
cmp samples/PAPER_EXAMPLE3.MPF "$scratch/PAPER_EXAMPLE3.MPF.bak"
if ls "$scratch"/.PAPER_EXAMPLE3.MPF.sinuprep-* >/dev/null 2>&1; then
  echo "a temporary file was left beside the program"
  exit 1
fi
# A verbatim path (\\?\Z:\...), the form long paths and UNC shares take:
# read, and named in SARIF by the path it stands for.
cp tests/fixtures/lint/N022_trigger.mpf "$scratch/VERBATIM.MPF"
wine "$out/sinuprep.exe" check --format sarif "\\\\?\\Z:${scratch//\//\\}\\VERBATIM.MPF" > "$scratch/verbatim.sarif" || true
grep -q "\"uri\": \"file:///Z:${scratch}/VERBATIM.MPF\"" "$scratch/verbatim.sarif"
# A program with errors: exit 1, the finding at its line and column.
set +e
wine "$out/sinuprep.exe" check --format short 'tests\fixtures\lint\N022_trigger.mpf' > "$scratch/check.txt"
status=$?
set -e
[[ $status -eq 1 ]] || { echo "check exited $status, not 1"; exit 1; }
grep -q "N022_trigger.mpf:2:12: error\[N022\]" "$scratch/check.txt"

# The command-line tests, built above in the release profile (a debug build
# of every dependency would take minutes more), run by Wine (cargo's runner
# for the target). Each test executable and the binary it runs need the stub
# DLL beside them. What Wine cannot run (symbolic links, FIFOs, modes and
# owners) is left out in the tests, by `cfg`, each with its reason.
cp "$out/bcryptprimitives.dll" "$out/deps/"
CARGO_TARGET_X86_64_PC_WINDOWS_GNU_RUNNER=wine \
  cargo test --release --locked --target "$target" --test cli --test files
echo "Windows binary under Wine: rewrite (file, stdin, in place), check, and the command-line tests as on Linux"
