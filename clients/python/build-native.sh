#!/usr/bin/env bash
# Builds the native library of the match engine (NativeAOT, include/urwpgsim2d.h) that
# urwpgsim2d.vec.FishVecEnv loads: clients/python/urwpgsim2d/native/liburwpgsim2d.so.
# Needs the .NET SDK and a C toolchain: clang, or gcc (used when clang is not installed).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
rid="linux-$(uname -m | sed -e 's/x86_64/x64/' -e 's/aarch64/arm64/')"
linker=()
command -v clang >/dev/null 2>&1 || linker=(-p:CppCompilerAndLinker=gcc)
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
dotnet publish "$root/src/URWPGSim2D.Learning/URWPGSim2D.Learning.csproj" -c Release -r "$rid" -p:IlcInstructionSet=native "${linker[@]}" -o "$out" --nologo -v quiet
mkdir -p "$root/clients/python/urwpgsim2d/native"
cp "$out/URWPGSim2D.Learning.so" "$root/clients/python/urwpgsim2d/native/liburwpgsim2d.so"
echo "built clients/python/urwpgsim2d/native/liburwpgsim2d.so"
