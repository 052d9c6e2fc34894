#!/usr/bin/env python3
"""Fails when a module includes a module above it in the documented dependency order.

The order is read from docs/DESIGN.md, from the line that starts with "Dependency order:" and
names the modules in backquotes, lowest first. A file of module M (include/rigdesign/M/... or
src/M/...) may include public headers "rigdesign/N/..." only for N at or below M, and private
headers "N/..." (relative to src/) only of its own module. Usage: check_layers.py ROOT
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def documented_order(root):
    design = root / 'docs' / 'DESIGN.md'
    for line in design.read_text(encoding='utf-8').splitlines():
        if line.startswith('Dependency order:'):
            return re.findall(r'`([a-z_]+)`', line)
    sys.exit(f'{design}: no line starting with "Dependency order:"')


def module_of(path, root):
    parts = path.relative_to(root).parts
    if parts[0] == 'include' and len(parts) > 3:
        return parts[2]
    if parts[0] == 'src' and len(parts) > 2:
        return parts[1]
    return None


def violations(root, order):
    rank = {name: i for i, name in enumerate(order)}
    found = []
    files = [*(root / 'include' / 'rigdesign').rglob('*.hpp'), *(root / 'src').rglob('*.[ch]pp')]
    for path in sorted(files):
        module = module_of(path, root)
        if module is None:
            continue
        if module not in rank:
            found.append(f'{path.relative_to(root)}: module "{module}" is not in the documented order')
            continue
        text = path.read_text(encoding='utf-8')
        for match in INCLUDE.finditer(text):
            target = match.group(1)
            line = text.count('\n', 0, match.start()) + 1
            where = f'{path.relative_to(root)}:{line}'
            head, _, rest = target.partition('/')
            if head == 'rigdesign':
                used = rest.partition('/')[0]
                if used in rank and rank[used] > rank[module]:
                    found.append(f'{where}: {module} includes "{target}" of {used}, which comes '
                                 f'after it in the dependency order')
            elif rest and head in rank and head != module:
                found.append(f'{where}: {module} includes "{target}", a header private to {head}')
    return found


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
    order = documented_order(root)
    found = violations(root, order)
    for message in found:
        print(message)
    print(f'layering: {len(found)} violations in the order {" < ".join(order)}')
    return 1 if found else 0


if __name__ == '__main__':
    sys.exit(main())
