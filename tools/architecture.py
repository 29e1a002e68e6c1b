#!/usr/bin/python3
"""Writes and checks the list of every tracked file in docs/architecture.md, room by room.

    tools/architecture.py --write    rewrite the list between the markers from `git ls-files`
    tools/architecture.py --check    exit 1 naming every listed file that does not exist, every
                                     tracked file the list misses, a list that is out of date, and
                                     every include or import that the rooms table does not allow

A file's line is its own first header sentence (a module docstring, or the comment block a file
starts with, after a shebang or an XML declaration; a Markdown file's title), so that the fact
lives in the file. A file without one is described in the doc's table of descriptions, by path or
by a glob (`compat/gazebo_msgs/msg/*.msg`) that the list shows as one line and the check expands.
A `.cpp` without a header of its own shares the line of the `.h` beside it, or names the header
of include/bullet_plant/ it implements. The rooms (a folder,
its floor and what it may include) are the doc's rooms table: every tracked file belongs to the
room with the longest matching folder; a file in no room, or in a new sub-folder of a room that is
divided into rooms (src/plant/), is an error naming it. The rooms table's "may include" says which
rooms a room's C/C++ files may `#include "..."` (resolved as the compiler does, through the folders
CMakeLists.txt puts on the include path) and its Python files may import of the package's own
modules; an include it does not allow is an error naming the file, the line, the included file and
the rule.
Standard library only: runs with /usr/bin/python3 before anything is built.
"""
import argparse
import ast
import fnmatch
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join('docs', 'architecture.md')
BEGIN = '<!-- BEGIN FILES: written by tools/architecture.py --write; do not edit by hand -->'
END = '<!-- END FILES -->'
ROOMS_BEGIN = '<!-- BEGIN ROOMS: read by tools/architecture.py -->'
ROOMS_END = '<!-- END ROOMS -->'
DESCRIPTIONS_BEGIN = '<!-- BEGIN DESCRIPTIONS: read by tools/architecture.py -->'
DESCRIPTIONS_END = '<!-- END DESCRIPTIONS -->'
LONGEST = 200  # characters of a header sentence kept in the list

HASH_COMMENT = ('.sh', '.yaml', '.yml', '.msg', '.srv', '.action', '.csv', '.ini', '.txt', '.cfg', '.cmake', '.pc')
SLASH_COMMENT = ('.cpp', '.h', '.hpp', '.cc', '.hh', '.js', '.proto')
XML_COMMENT = ('.xml', '.launch', '.world', '.xacro', '.test', '.urdf', '.sdf', '.config', '.dae', '.html')


def tracked_files(root=ROOT):
    out = subprocess.run(['git', 'ls-files', '-z'], cwd=root, check=True, stdout=subprocess.PIPE).stdout
    return sorted(p for p in out.decode().split('\0') if p)


def _section(text, begin, end, doc=DOC):
    try:
        start = text.index(begin) + len(begin)
        stop = text.index(end, start)
    except ValueError:
        sys.exit(f'{doc}: the markers {begin!r} and {end!r} are missing: restore them around the section')
    return start, stop


def _table_rows(block):
    """The cells of a Markdown table's body rows (header and rule skipped)."""
    rows = []
    for line in block.splitlines():
        line = line.strip()
        if not line.startswith('|') or set(line) <= set('|-: '):
            continue
        rows.append([cell.strip() for cell in line.strip('|').split('|')])
    return rows[1:]


def _code(cell):
    return cell.strip().strip('`').strip()


def read_rooms(text):
    """[(folder, floor)] from the rooms table; '' is the top-level room."""
    start, stop = _section(text, ROOMS_BEGIN, ROOMS_END)
    rooms = []
    for cells in _table_rows(text[start:stop]):
        folder = _code(cells[1])
        rooms.append(('' if folder in ('(top level)', '/') else folder.rstrip('/'), cells[0]))
    return rooms


def read_descriptions(text):
    """[(path or glob, description)] from the table of descriptions."""
    start, stop = _section(text, DESCRIPTIONS_BEGIN, DESCRIPTIONS_END)
    return [(_code(cells[0]), cells[1]) for cells in _table_rows(text[start:stop])]


def _first_sentence(paragraph):
    text = ' '.join(paragraph.split())
    match = re.search(r'(?<![A-Z0-9.][a-z])\.(\s|$)', text)  # not the dot of "e.g." or "Fig."
    if match:
        text = text[:match.start() + 1]
    if len(text) > LONGEST:
        cut = max(text.rfind(mark, 0, LONGEST) for mark in (': ', '; ', ', '))
        text = (text[:cut] if cut > 0 else text[:LONGEST].rsplit(' ', 1)[0]) + ' ...'
    return text


def _markdown(text):
    """A header sentence as Markdown shows it verbatim: `<plugin>` is no HTML tag, `Joint*` no emphasis."""
    return text.replace('&', '&amp;').replace('<', '&lt;').replace('>', '&gt;').replace('*', '\\*')


def _comment_block(lines, marker):
    block = []
    for line in lines:
        stripped = line.strip()
        if not stripped.startswith(marker):
            break
        body = stripped[len(marker):].strip()
        if not body and block:
            break
        if body:
            block.append(body)
    return ' '.join(block)


def header_of(path, root=ROOT):
    """The first sentence of the comment or docstring a file starts with, or None."""
    full = os.path.join(root, path)
    name = os.path.basename(path)
    # a template (gazebo-config.cmake.in) is commented as what it makes
    ext = os.path.splitext(name[:-3] if name.endswith('.in') else name)[1]
    try:
        with open(full, encoding='utf-8') as f:
            text = f.read()
    except (UnicodeDecodeError, IsADirectoryError, FileNotFoundError):
        return None
    lines = text.splitlines()
    if ext == '.md':
        for line in lines:
            if line.startswith('# '):
                return line[2:].strip()
        return None
    shebang = bool(lines) and lines[0].startswith('#!')
    if ext == '.py' or (shebang and 'python' in lines[0]):
        try:
            docstring = ast.get_docstring(ast.parse(text))
        except SyntaxError:
            docstring = None
        if docstring:
            return _first_sentence(docstring.split('\n\n')[0])
        body = [l for l in lines[1 if shebang else 0:] if not l.startswith('# -*-')]
        block = _comment_block(body, '#')
        return _first_sentence(block) if block else None
    if ext in SLASH_COMMENT:
        block = _comment_block(lines, '//')
        return _first_sentence(block) if block else None
    if ext in HASH_COMMENT or name == 'Makefile' or shebang:
        block = _comment_block(lines[1 if shebang else 0:], '#')
        return _first_sentence(block.lstrip('#').strip()) if block else None
    if ext in XML_COMMENT:
        rest = text.lstrip()
        if rest.startswith('<?xml'):
            rest = rest[rest.index('?>') + 2:].lstrip()
        if rest.startswith('<!--'):
            comment = rest[4:rest.index('-->')]
            return _first_sentence(comment.strip().split('\n\n')[0])
        return None
    return None


def _public_header(cpp):
    """The header of include/bullet_plant/ a plant source file implements (same name)."""
    return 'include/bullet_plant/' + os.path.basename(cpp)[:-4] + '.h'


def room_of(path, rooms):
    best = None
    for folder, _ in rooms:
        if folder == '' and '/' not in path or folder and path.startswith(folder + '/'):
            if best is None or len(folder) > len(best):
                best = folder
    return best


def _in_unlisted_subroom(path, room, rooms):
    """Whether a file sits in a sub-folder of a room whose other sub-folders are rooms of their own
    (src/plant/: a new folder there is a new room, with a floor, not part of its parent)."""
    divided = any(folder.startswith(room + '/') for folder, _ in rooms) if room else False
    return divided and os.path.dirname(path) != room


def listing(files, rooms, descriptions, root=ROOT):
    """{room: [(paths, line text)]}, and the errors that keep a file from being described."""
    errors = []
    described = {}  # path -> (key, description): a glob covers all its files on one line
    for pattern, description in descriptions:
        matches = [p for p in files if fnmatch.fnmatchcase(p, pattern)]
        if not matches:
            errors.append(f'{DOC}: the description of {pattern} matches no tracked file: '
                          'remove its row or correct the path')
        for p in matches:
            described.setdefault(p, (pattern, description))
    headers = {p: header_of(p, root) for p in files}
    for pattern, _ in descriptions:
        if not any(c in pattern for c in '*?[') and headers.get(pattern):
            errors.append(f'{DOC}: {pattern} is described twice, by its header and by the table of '
                          'descriptions: remove its row (its header says it)')
    lines = {}
    done = set()
    for p in files:
        if p in done:
            continue
        room = room_of(p, rooms)
        if room is None:
            errors.append(f'{p} is in no room: add a row for its folder to the rooms table of {DOC}')
            continue
        if _in_unlisted_subroom(p, room, rooms):
            errors.append(f'{p} is in a folder of {room}/, which is divided into rooms: add a row for '
                          f'{os.path.dirname(p)}/ to the rooms table of {DOC} (its floor, what it may include)')
            continue
        if p in described:
            key, description = described[p]
            group = [q for q in files if described.get(q, (None,))[0] == key]
            entry = (key, description, group)
        elif headers[p]:
            entry = (p, _markdown(headers[p]), [p])
        elif p.endswith('.cpp') and headers.get(p[:-4] + '.h'):
            entry = (p, _markdown(headers[p[:-4] + '.h']), [p, p[:-4] + '.h'])
        elif p.endswith('.cpp') and headers.get(_public_header(p)):
            entry = (p, f'implements `{_public_header(p)}`', [p])
        elif not os.path.lexists(os.path.join(root, p)):
            errors.append(f'{p} is tracked but not in the working tree: git rm it, or restore it')
            continue
        else:
            errors.append(f'{p} has no description: give it a header comment or docstring, '
                          f'or a row in the table of descriptions of {DOC}')
            continue
        if p.endswith('.h') and (p[:-2] + '.cpp') in files and not headers.get(p[:-2] + '.cpp') \
                and (p[:-2] + '.cpp') not in described:
            entry = (entry[0], entry[1], sorted(set(entry[2]) | {p[:-2] + '.cpp'}))
        done.update(entry[2])
        lines.setdefault(room, []).append(entry)
    return lines, errors


def render(lines, rooms):
    out = ['']
    for folder, floor in rooms:
        entries = lines.get(folder)
        if not entries:
            continue
        out.append(f'### {folder + "/" if folder else "(top level)"} (floor {floor})')
        out.append('')
        for key, description, group in entries:
            if len(group) == 1 and key == group[0]:
                name = f'[`{key}`](../{key})'
            elif any(c in key for c in '*?['):
                name = f'`{key}` ({len(group)} files)'
            else:
                name = ', '.join(f'[`{p}`](../{p})' for p in group)
            out.append(f'- {name}: {description}')
        out.append('')
    return '\n'.join(out)


# The "may include" cell: before the first ';', the rooms (backticked, a sibling's name or a path
# from the top) or these words, comma-separated; after it, prose on outside libraries, unchecked.
EVERY_ROOM_BELOW = 'every room below'
NOTHING = ('nothing', '-', '')
CMAKE_KEYWORDS = {'PUBLIC', 'PRIVATE', 'INTERFACE', 'SYSTEM', 'BEFORE', 'AFTER'}
C_FAMILY = ('.c', '.cc', '.cpp', '.cxx', '.h', '.hh', '.hpp', '.hxx', '.inl')
QUOTED_INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.MULTILINE)
PACKAGE = 'tianracer_description'


def _room_name(folder):
    return folder + '/' if folder else '(top level)'


def read_include_rules(text):
    """({room: set of rooms it may include, itself among them}, errors naming a cell the check cannot read
    or a room that names one on its own floor or above)."""
    start, stop = _section(text, ROOMS_BEGIN, ROOMS_END)
    rows = _table_rows(text[start:stop])
    rooms = read_rooms(text)
    floors = {}
    errors = []
    for folder, floor in rooms:
        try:
            floors[folder] = int(floor)
        except ValueError:
            errors.append(f'{DOC}: the floor of {_room_name(folder)} is {floor!r}: write a number')
            floors[folder] = 0
    rules = {}
    for (folder, _), cells in zip(rooms, rows):
        allowed = {folder}
        rooms_part = cells[3].split(';', 1)[0].strip() if len(cells) > 3 else ''
        for item in (i.strip() for i in rooms_part.split(',')):
            if item == EVERY_ROOM_BELOW:
                allowed |= {f for f in floors if floors[f] < floors[folder]}
                continue
            if item in NOTHING:
                continue
            quoted = re.fullmatch(r'`([^`]+)`', item)
            name = quoted.group(1).rstrip('/') if quoted else None
            sibling = os.path.join(os.path.dirname(folder), name) if quoted and folder else name
            room = sibling if sibling in floors else name if name in floors else None
            if room is None:
                errors.append(f'{DOC}: {_room_name(folder)} may include {item!r}, which is no room: name rooms '
                              f'in backticks (`physics/`, `include/bullet_plant/`) or write "{EVERY_ROOM_BELOW}", '
                              'and put outside libraries after a ";"')
            elif floors[room] >= floors[folder]:
                errors.append(f'{DOC}: {_room_name(folder)} (floor {floors[folder]}) may include {_room_name(room)}, '
                              f'which is on floor {floors[room]}: a room includes only rooms on lower floors; '
                              'renumber the floors or drop the room')
            else:
                allowed.add(room)
        rules[folder] = allowed
    return rules, floors, errors


def _cmake_text(root):
    """CMakeLists.txt and the cmake/*.cmake files it includes, without their comments ('' where there
    is none)."""
    paths = [os.path.join(root, 'CMakeLists.txt')]
    cmake_folder = os.path.join(root, 'cmake')
    if os.path.isdir(cmake_folder):
        paths += sorted(os.path.join(cmake_folder, n) for n in os.listdir(cmake_folder) if n.endswith('.cmake'))
    text = ''
    for path in paths:
        if os.path.exists(path):
            with open(path, encoding='utf-8') as f:
                text += re.sub(r'#[^\n]*', '', f.read()) + '\n'
    return text


def cmake_include_dirs(root=ROOT):
    """The project's own folders CMakeLists.txt puts on the include path, in order (every target's:
    a quoted include that resolves only through another target's folder fails to compile anyway)."""
    cmake = _cmake_text(root)
    dirs = []
    for match in re.finditer(r'\b(target_include_directories|include_directories)\s*\(([^)]*)\)', cmake, re.I):
        args = match.group(2).split()
        for arg in args[1:] if match.group(1).lower().startswith('target') else args:
            arg = re.sub(r'^\$\{(PROJECT_SOURCE_DIR|CMAKE_CURRENT_SOURCE_DIR|CMAKE_SOURCE_DIR)\}/?', '', arg)
            if arg in CMAKE_KEYWORDS or '$' in arg or os.path.isabs(arg):
                continue  # another package's folders: what is found there is no room of ours
            arg = os.path.normpath(arg)
            if arg not in dirs:
                dirs.append(arg)
    return dirs


def python_module_rooms(root=ROOT):
    """(the folder setup.py's package_dir puts the package in, {built module: folder of its sources})
    for the pybind11 modules CMakeLists.txt builds into the package (OUTPUT_NAME)."""
    setup = os.path.join(root, 'setup.py')
    match = None
    if os.path.exists(setup):
        with open(setup, encoding='utf-8') as f:
            match = re.search(r"package_dir\s*=\s*\{\s*['\"]['\"]\s*:\s*['\"]([^'\"]+)['\"]", f.read())
    package_root = match.group(1) if match else ''
    cmake = _cmake_text(root)
    built = {}
    for match in re.finditer(r'\bpybind11_add_module\s*\(\s*(\S+)([^)]*)\)', cmake):
        target, sources = match.group(1), [s for s in match.group(2).split() if '.' in s]
        name = re.search(r'set_target_properties\s*\(\s*' + re.escape(target) +
                         r'\s[^)]*OUTPUT_NAME\s+([^\s)]+)', cmake)
        if sources:
            built[f'{PACKAGE}.{name.group(1) if name else target}'] = os.path.dirname(sources[0])
    return package_root, built


def _resolve_include(path, name, include_dirs, tracked):
    """The tracked file `#include "name"` in path means: its own folder first, then the include path."""
    for folder in [os.path.dirname(path)] + include_dirs:
        candidate = os.path.normpath(os.path.join(folder, name))
        if candidate in tracked:
            return candidate
    return None  # another package's header, found through its ${..._INCLUDE_DIRS}


def _imported_modules(path, text):
    """[(line, module)] for every import of the package's own modules, relative ones resolved."""
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return []
    parts = path[:-3].split('/') if path.endswith('.py') else []
    package = parts[parts.index(PACKAGE):-1] if PACKAGE in parts else []
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ''
            if node.level:
                if not package or node.level > len(package):
                    continue
                base = '.'.join(package[:len(package) - node.level + 1] + ([base] if base else []))
            found += [(node.lineno, f'{base}.{alias.name}') for alias in node.names]  # a module or a name in one
    return [(line, module) for line, module in found if module == PACKAGE or module.startswith(PACKAGE + '.')]


def _resolve_module(module, package_root, built, tracked):
    """The tracked file (or the folder of a built module's sources) an import of module reaches."""
    parts = module.split('.')
    while parts:
        name = '.'.join(parts)
        if name in built:
            return built[name] + '/'
        base = os.path.join(package_root, *parts)
        for candidate in (base + '.py', os.path.join(base, '__init__.py')):
            if candidate in tracked:
                return candidate
        parts.pop()  # `from package.module import name`: the name is no module
    return None


def include_violations(text, files, root=ROOT):
    """Every C/C++ `#include "..."` and import of the package's own modules that the rooms table
    does not allow, named by file and line, and the table's own errors."""
    rules, floors, errors = read_include_rules(text)
    if errors:
        return errors
    rooms = read_rooms(text)
    include_dirs = cmake_include_dirs(root)
    package_root, built = python_module_rooms(root)
    tracked = set(files)
    for path in files:
        ext = os.path.splitext(path)[1]
        room = room_of(path, rooms)
        if room is None or ext not in C_FAMILY + ('.py', ''):
            continue  # a file in no room is named by the listing's check
        try:
            with open(os.path.join(root, path), encoding='utf-8') as f:
                text_of_file = f.read()
        except (UnicodeDecodeError, FileNotFoundError, IsADirectoryError):
            continue
        python = ext == '.py' or re.match(r'#!.*python', text_of_file) is not None
        if not python and ext not in C_FAMILY:
            continue
        if python:
            reached = [(line, f'imports {module} from', _resolve_module(module, package_root, built, tracked))
                       for line, module in _imported_modules(path, text_of_file)]
        else:
            reached = [(text_of_file.count('\n', 0, m.start()) + 1, 'includes',
                        _resolve_include(path, m.group(1), include_dirs, tracked))
                       for m in QUOTED_INCLUDE.finditer(text_of_file)]
        for line, verb, target in reached:
            if target is None:
                continue
            target_room = room_of(target + 'x' if target.endswith('/') else target, rooms)
            if target_room in rules[room]:
                continue
            allowed = ', '.join(_room_name(r) for r in sorted(rules[room], key=lambda r: (floors[r], r)))
            errors.append(f'{path}:{line} {verb} {target} (floor {floors.get(target_room)}): {_room_name(room)} '
                          f'(floor {floors[room]}) may include only {allowed}: include through a room it may, '
                          f'or change its "may include" in the rooms table of {DOC}')
    return errors


def listed_paths(section, files):
    """Every path the written list names, globs expanded against the tracked files."""
    paths = set()
    for match in re.finditer(r'^- (.*?): ', section, re.MULTILINE):
        for name in re.findall(r'`([^`]+)`', match.group(1)):
            if any(c in name for c in '*?['):
                expanded = [p for p in files if fnmatch.fnmatchcase(p, name)]
                paths.update(expanded or [name])
            else:
                paths.add(name)
    return paths


def check(text, files, root=ROOT):
    """The errors of the doc against the tracked files (an empty list: all is well)."""
    rooms = read_rooms(text)
    descriptions = read_descriptions(text)
    start, stop = _section(text, BEGIN, END)
    section = text[start:stop]
    errors = []
    listed = listed_paths(section, files)
    tracked = set(files)
    for p in sorted(listed - tracked):
        errors.append(f'{DOC} lists {p}, which is not a tracked file: run tools/architecture.py --write')
    for p in sorted(tracked - listed):
        errors.append(f'{DOC} misses the tracked file {p}: run tools/architecture.py --write')
    for folder, _ in rooms:
        if folder and not any(p.startswith(folder + '/') for p in files):
            errors.append(f'{DOC}: the room {folder}/ holds no tracked file: remove its row')
    lines, listing_errors = listing(files, rooms, descriptions, root)
    errors += listing_errors
    errors += include_violations(text, files, root)
    if not errors and render(lines, rooms) != section:
        errors.append(f'{DOC}: the file list is out of date (a header or a description changed): '
                      'run tools/architecture.py --write')
    return errors


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument('--write', action='store_true', help='rewrite the file list in ' + DOC)
    mode.add_argument('--check', action='store_true', help='exit 1 when the list and git ls-files differ')
    args = parser.parse_args()
    path = os.path.join(ROOT, DOC)
    with open(path, encoding='utf-8') as f:
        text = f.read()
    files = tracked_files()
    if args.check:
        errors = check(text, files)
        for error in errors:
            print(error, file=sys.stderr)
        return 1 if errors else 0
    rooms = read_rooms(text)
    lines, errors = listing(files, rooms, read_descriptions(text))
    for error in errors:
        print(error, file=sys.stderr)
    start, stop = _section(text, BEGIN, END)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text[:start] + render(lines, rooms) + text[stop:])
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
