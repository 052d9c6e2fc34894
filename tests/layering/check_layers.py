#!/usr/bin/env python3
"""Fails when a module includes a module that docs/DESIGN.md does not let it use.

Two facts are read from docs/DESIGN.md: the line that starts with "Dependency order:" and names
the modules in backquotes, lowest first, and the markdown table right after it, with columns
"module | owns | uses", whose "uses" cells name modules in backquotes (anything else in the
cell, such as Eigen or a few words of prose, is ignored). A file of module M
(include/rigdesign/M/... or src/M/...) may include public headers "rigdesign/N/..." only for
N == M or N reachable from M through the "uses" column, and private headers "N/..." (relative
to src/) only of its own module. The table must agree with the order: a module uses only
modules before it. Where ROOT/src/CMakeLists.txt declares the module libraries
(`rigdesign_module(NAME USES ...)`, cmake/rigdesign_module.cmake), each declared module must
reach exactly the modules the table lets it reach, so the linker enforces the documented
design. Usage: check_layers.py ROOT
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)
NAME = re.compile(r'`([a-z_]+)`')
# A cell may hold "\|"; only unescaped bars separate cells.
CELL_BAR = re.compile(r'(?<!\\)\|')


def cells(row):
    return [cell.strip() for cell in CELL_BAR.split(row.strip().strip('|'))]


def documented_design(root):
    """Returns (order, uses): the modules lowest first, and each module's used modules as listed."""
    design = root / 'docs' / 'DESIGN.md'
    lines = design.read_text(encoding='utf-8').splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith('Dependency order:')), None)
    if start is None:
        sys.exit(f'{design}: no line starting with "Dependency order:"')
    order = NAME.findall(lines[start])
    # The table is the first one after the order line; prose may sit between them.
    first = next((i for i in range(start + 1, len(lines)) if lines[i].startswith('|')), None)
    if first is None:
        sys.exit(f'{design}: no module table after the "Dependency order:" line')
    header = cells(lines[first])
    if 'module' not in header or 'uses' not in header:
        sys.exit(f'{design}:{first + 1}: the module table needs a "module" and a "uses" column')
    module_column, uses_column = header.index('module'), header.index('uses')
    uses = {}
    for number in range(first + 2, len(lines)):  # + 2 skips the |---| row
        if not lines[number].startswith('|'):
            break
        row = cells(lines[number])
        module = NAME.fullmatch(row[module_column]) if len(row) == len(header) else None
        if module is None:
            sys.exit(f'{design}:{number + 1}: a module table row needs {len(header)} cells and '
                     f'one backquoted module name in the "module" column')
        uses[module.group(1)] = NAME.findall(row[uses_column])
    return order, uses


def table_violations(order, uses):
    """The table and the order line must describe one design; say where they part."""
    found = []
    rank = {name: i for i, name in enumerate(order)}
    for name in order:
        if name not in uses:
            found.append(f'docs/DESIGN.md: module "{name}" is in the dependency order but has no '
                         f'row in the module table')
    for module, used_modules in uses.items():
        if module not in rank:
            found.append(f'docs/DESIGN.md: module "{module}" has a row in the module table but is '
                         f'not in the dependency order')
            continue
        for used in used_modules:
            if used not in uses:
                found.append(f'docs/DESIGN.md: the uses column of {module} names "{used}", which '
                             f'is not a module of the table')
            elif used in rank and rank[used] >= rank[module]:
                found.append(f'docs/DESIGN.md: the uses column of {module} names {used}, which '
                             f'does not come before it in the dependency order')
    return found


def reachable(uses):
    """Each module's allowed modules: itself and every module its uses column leads to."""
    allowed = {}
    for module in uses:
        seen, todo = {module}, [module]
        while todo:
            for used in uses.get(todo.pop(), []):
                if used not in seen:
                    seen.add(used)
                    todo.append(used)
        allowed[module] = seen
    return allowed


def module_of(path, root):
    parts = path.relative_to(root).parts
    if parts[0] == 'include' and len(parts) > 3:
        return parts[2]
    if parts[0] == 'src' and len(parts) > 2:
        return parts[1]
    return None


def include_violations(root, order, uses):
    rank = {name: i for i, name in enumerate(order)}
    allowed = reachable(uses)
    found = []
    files = [*(root / 'include' / 'rigdesign').rglob('*.hpp'), *(root / 'src').rglob('*.[ch]pp')]
    for path in sorted(files):
        module = module_of(path, root)
        if module is None:
            continue
        if module not in uses:
            found.append(f'{path.relative_to(root)}: module "{module}" is not in the module table')
            continue
        text = path.read_text(encoding='utf-8')
        for match in INCLUDE.finditer(text):
            target = match.group(1)
            line = text.count('\n', 0, match.start()) + 1
            where = f'{path.relative_to(root)}:{line}'
            head, _, rest = target.partition('/')
            if head == 'rigdesign':
                used = rest.partition('/')[0]
                if used not in uses or used in allowed[module]:
                    continue
                # An upward include breaks the order itself, the worse news; say that first.
                if used in rank and module in rank and rank[used] > rank[module]:
                    found.append(f'{where}: {module} includes "{target}" of {used}, which comes '
                                 f'after it in the dependency order')
                else:
                    found.append(f'{where}: {module} includes "{target}" of {used}, which the '
                                 f'uses column of {module} in docs/DESIGN.md does not allow')
            elif rest and head in uses and head != module:
                found.append(f'{where}: {module} includes "{target}", a header private to {head}')
    return found


MODULE_CALL = re.compile(r'^rigdesign_module\(([^)]*)\)', re.MULTILINE)


def cmake_violations(root, uses):
    """The module libraries of src/CMakeLists.txt must link what the table lets them use."""
    cmake = root / 'src' / 'CMakeLists.txt'
    if not cmake.exists():
        return []
    declared = {}
    for match in MODULE_CALL.finditer(cmake.read_text(encoding='utf-8')):
        words = match.group(1).split()
        name, section, used = words[0], None, []
        for word in words[1:]:
            if word in ('USES', 'LIBS'):
                section = word
            elif section == 'USES':
                used.append(word)
        declared[name] = used
    allowed, linked = reachable(uses), reachable(declared)
    found = []
    for module, used in sorted(declared.items()):
        if module not in uses:
            found.append(f'src/CMakeLists.txt: module library "{module}" has no row in the table')
            continue
        if linked[module] != allowed[module]:
            extra = sorted(linked[module] - allowed[module])
            missing = sorted(allowed[module] - linked[module])
            found.append(f'src/CMakeLists.txt: {module} links {", ".join(extra) or "nothing more"}'
                         f' beyond docs/DESIGN.md and lacks {", ".join(missing) or "nothing"}')
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
    order, uses = documented_design(root)
    found = (table_violations(order, uses) + include_violations(root, order, uses) +
             cmake_violations(root, uses))
    for message in found:
        print(message)
    print(f'layering: {len(found)} violations in the order {" < ".join(order)}')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
