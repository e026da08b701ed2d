#!/usr/bin/env python3
"""Lists the library's source files over --max-file lines and its functions over --max-function
lines (include/, src/, apps/, python/). A function is a brace block opened after a parameter list
at namespace or class scope; lambdas count towards the function that holds them.

Usage: check_sizes.py [--max-file 600] [--max-function 80] [--strict]
Prints one line per file or function over its limit; with --strict exits 1 when any is."""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
FOLDERS = ("include", "src", "apps", "python")
NOT_A_FUNCTION = re.compile(r"^\s*(namespace|class|struct|union|enum|extern)\b|=\s*$|\bdo\s*$")


def strip(text):
    """Source with comments, preprocessor lines, string and character literals blanked (newlines
    kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == "#" and (i == 0 or text[i - 1] == "\n"):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + " " * (min(j, n) - i - 1) + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    text = strip(path.read_text(encoding="utf-8"))
    scopes = []  # per open brace: "function", "scope" (namespace/class) or "block"
    head_start, line = 0, 1
    found = []
    for i, c in enumerate(text):
        if c == "\n":
            line += 1
        elif c == "{":
            head = text[head_start:i]
            inside_function = "function" in scopes
            if not inside_function and ")" in head and not NOT_A_FUNCTION.search(head.strip()):
                name = re.findall(r"([~\w:<>]+)\s*\(", head)
                scopes.append("function")
                found.append([name[0] if name else "?", line, None])
            elif not inside_function:
                scopes.append("scope")
            else:
                scopes.append("block")
            head_start = i + 1
        elif c == "}":
            kind = scopes.pop() if scopes else "scope"
            if kind == "function":
                for f in reversed(found):
                    if f[2] is None:
                        f[2] = line
                        break
            head_start = i + 1
        elif c == ";" and "function" not in scopes:
            head_start = i + 1
    return [(name, start, end - start + 1) for name, start, end in found if end is not None]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--max-file", type=int, default=600)
    parser.add_argument("--max-function", type=int, default=80)
    parser.add_argument("--strict", action="store_true")
    args = parser.parse_args()
    over = 0
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix not in (".hpp", ".cpp", ".h"):
                continue
            rel = path.relative_to(ROOT)
            lines = path.read_text(encoding="utf-8").count("\n")
            if lines > args.max_file:
                print(f"file     {lines:5d} lines  {rel}")
                over += 1
            for name, start, length in functions(path):
                if length > args.max_function:
                    print(f"function {length:5d} lines  {rel}:{start} {name}")
                    over += 1
    print(f"{over} over the limits (file {args.max_file}, function {args.max_function} lines)")
    return 1 if args.strict and over else 0


if __name__ == "__main__":
    sys.exit(main())
