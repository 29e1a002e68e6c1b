"""Every relative link of README.md, README.zh-CN.md and docs/*.md leads to a file of the
repository, and every #anchor to a heading of its page (GitHub's anchors: lower case, punctuation
dropped, spaces as hyphens)."""
import glob
import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAGES = sorted(['README.md', 'README.zh-CN.md']
               + [os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, 'docs', '*.md'))])
LINK = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)\)')


def prose(text):
    """The text without code: fenced and indented blocks and inline code spans hold no links."""
    text = re.sub(r'^```.*?^```', '', text, flags=re.MULTILINE | re.DOTALL)
    text = re.sub(r'^(?: {4}|\t).*$', '', text, flags=re.MULTILINE)
    return re.sub(r'`[^`\n]*`', '', text)


def anchors(path):
    """The anchors GitHub gives the headings of a Markdown file (a repeated one gets -1, -2, ...)."""
    with open(path, encoding='utf-8') as f:
        text = re.sub(r'^```.*?^```', '', f.read(), flags=re.MULTILINE | re.DOTALL)
    seen = {}
    for heading in re.findall(r'^#{1,6} (.*)$', text, re.MULTILINE):
        slug = re.sub(r'[^\w\- ]', '', heading.replace('`', '').strip().lower()).replace(' ', '-')
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        yield slug if count == 0 else f'{slug}-{count}'


def links(page):
    with open(os.path.join(ROOT, page), encoding='utf-8') as f:
        for target in LINK.findall(prose(f.read())):
            if not re.match(r'^[a-z]+:', target):  # http:, https:, mailto: are not checked here
                yield target


@pytest.mark.parametrize('page', PAGES)
def test_every_relative_link_leads_to_a_file_and_heading(page):
    broken = []
    for target in links(page):
        path, _, anchor = target.partition('#')
        full = os.path.normpath(os.path.join(ROOT, os.path.dirname(page), path)) if path \
            else os.path.join(ROOT, page)
        if not os.path.exists(full):
            broken.append(f'{target}: no file {os.path.relpath(full, ROOT)}')
        elif anchor and full.endswith('.md') and anchor not in set(anchors(full)):
            broken.append(f'{target}: no heading with the anchor #{anchor} in {os.path.relpath(full, ROOT)}')
    assert not broken, f'{page}: ' + '; '.join(broken)


def test_the_check_finds_a_broken_link_and_a_broken_anchor(tmp_path):
    page = tmp_path / 'page.md'
    page.write_text('# Title\n\n[ok](#title) [gone](missing.md) [bad](#nowhere)\n', encoding='utf-8')
    assert list(anchors(str(page))) == ['title']
    assert [t for t in LINK.findall(prose(page.read_text(encoding='utf-8')))] == ['#title', 'missing.md', '#nowhere']
