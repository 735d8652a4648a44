#!/usr/bin/env python3
"""The structure the architecture promises, checked on the source tree.

Prints one verdict line per rule (and the offenders), exit code 1 if any
rule fails:
  - the method names are found, one for every registration (else the next
    rule would hold vacuously);
  - no method name as a string literal outside source/lcp/solvers/ (the
    driver, the scenes and the application learn methods from the registry);
  - include/unilateral/ mirrors source/ one to one (a method's file under
    source/lcp/solvers/ is a plugin with no header; a header-only template
    says so ("header-only"); a source that implements part of a class
    declared beside it is named in that header ("In output.cc: ..."); a
    private header lives beside the sources that include it);
  - no arrow from a lower layer up: base includes no lcp, fe or scenes; lcp
    and fe include no scenes; lcp includes no fe;
  - no function in source/lcp/ over 120 lines.
Usage: check_structure.py [REPOSITORY]
"""
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), "..", ".."))
failed = False


def verdict(what, offenders):
    global failed
    print(f"{what}: {'yes' if not offenders else 'NO'}")
    for offender in offenders:
        print(f"  {offender}")
    failed = failed or bool(offenders)


def files(folder, suffixes):
    for directory, _, names in os.walk(os.path.join(root, folder)):
        for name in sorted(names):
            if name.endswith(suffixes):
                yield os.path.relpath(os.path.join(directory, name), root)


def read(path):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        return f.read()


code = [p for folder in ("source", "include", "app")
        for p in files(folder, (".cc", ".h"))]

# Method names, from the registrations. The names come from a pattern
# ('info.name = "..."'): if the registration style changed, no name would be
# found and the rule below would hold vacuously. So the names found must be
# as many as the registrations (UNILATERAL_REGISTER_SOLVER, one per method,
# the list the 'Method' selection is made of at run time), and not none.
solvers = "source/lcp/solvers/"
names = set()
registrations = 0
for path in files(solvers, (".cc",)):
    names.update(re.findall(r'info\.name\s*=\s*"(\w+)"', read(path)))
    registrations += len(re.findall(r"^\s*UNILATERAL_REGISTER_SOLVER\(\w+\)",
                                    read(path), re.MULTILINE))
verdict(f"method names found for every registration ({len(names)} names, "
        f"{registrations} registrations)",
        [] if names and len(names) == registrations else
        [f"{len(names)} names by 'info.name = \"...\"' in {solvers}, "
         f"{registrations} UNILATERAL_REGISTER_SOLVER lines"])
literal = [f"{path}: \"{name}\"" for path in code
           if not path.startswith(solvers)
           for name in sorted(names) if f'"{name}"' in read(path)]
verdict(f"no method name ({len(names)} registered) as a string literal "
        "outside source/lcp/solvers/", literal)

# include/ mirrors source/.
headers = {p[len("include/unilateral/"):-2] for p in files("include", (".h",))}
sources = {p[len("source/"):-3] for p in files("source", (".cc",))
           if not p.startswith(solvers)}
def named_by_a_header(source):
    """A source that implements part of a class whose header, in the
    mirrored folder, names it ("In output.cc: ...")."""
    folder = os.path.join("include/unilateral", os.path.dirname(source))
    return any(f"{os.path.basename(source)}.cc" in read(h)
               for h in files(folder, (".h",))
               if os.path.dirname(h) == folder)


unmatched = [f"source/{s}.cc has no include/unilateral/{s}.h"
             for s in sorted(sources - headers) if not named_by_a_header(s)]
unmatched += [f"include/unilateral/{h}.h has no source/{h}.cc"
              for h in sorted(headers - sources)
              if "header-only" not in read(f"include/unilateral/{h}.h")]
unmatched += [f"{p}: a header in source/ that no source beside it includes"
              for p in files("source", (".h",))
              if not any(f'"{os.path.basename(p)}"' in read(c)
                         for c in files(os.path.dirname(p), (".cc",)))]
verdict("include/unilateral/ mirrors source/ one to one", unmatched)

# Layers: what each may not include.
forbidden = {"base": ("lcp", "fe", "scenes"), "lcp": ("fe", "scenes"),
             "fe": ("lcp", "scenes")}
arrows = []
for path in code:
    parts = path.split("/")
    layer = parts[2] if parts[0] == "include" else parts[1]
    for target in forbidden.get(layer, ()):
        if re.search(rf"#include <unilateral/{target}/", read(path)):
            arrows.append(f"{path} includes unilateral/{target}/")
verdict("no include from a lower layer up (base < lcp, fe < scenes)", arrows)


def long_functions(path, limit):
    """Function bodies (a '{' that opens at depth 0 or 1 inside namespaces
    and classes after a signature ending in ')', 'const', 'override' ...)
    longer than @p limit lines."""
    lines = read(path).split("\n")
    result = []
    depth = 0
    scopes = []  # (kind, start line, depth at open)
    statement = ""
    for number, line in enumerate(lines, 1):
        stripped = re.sub(r'"(\\.|[^"\\])*"', '""', line.split("//")[0])
        for character in stripped:
            if character == "{":
                head = statement.strip()
                in_function = any(kind == "function" for kind, *_ in scopes)
                is_function = (not in_function and
                               re.search(r"\)\s*(const)?\s*(override)?\s*"
                                         r"(noexcept)?\s*(->\s*[\w:<>]+)?\s*$"
                                         r"|^\s*:.*\)\s*$", head) and
                               not re.match(r"(if|for|while|switch|catch|"
                                            r"else|do)\b", head) and
                               not re.search(r"\]\s*\([^)]*\)\s*"
                                             r"(mutable)?\s*(->\s*\S+)?\s*$",
                                             head))
                scopes.append(("function" if is_function else "block",
                               number))
                statement = ""
                depth += 1
            elif character == "}":
                depth -= 1
                kind, start = scopes.pop()
                if kind == "function" and number - start + 1 > limit:
                    result.append(f"{path}:{start}: "
                                  f"{number - start + 1} lines")
                statement = ""
            elif character == ";":
                statement = ""
            else:
                statement += character
        statement += " "
    return result


offenders = [offender for path in files("source/lcp", (".cc",))
             for offender in long_functions(path, 120)]
verdict("no function in source/lcp/ over 120 lines", offenders)

sys.exit(1 if failed else 0)
