"""docs/benchmarks.md, where each benchmark script keeps a section of its
own between two markers: the others leave it as it is."""
import os
import re

PAGE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "docs", "benchmarks.md")


def write_section(begin, end, section, page_path=PAGE):
    """Put section (which starts with begin and ends with end) in place of
    the page's (docs/benchmarks.md unless page_path names another), or at
    its end if it has none yet."""
    with open(page_path) as f:
        page = f.read()
    if begin in page:
        page = re.sub(re.escape(begin) + ".*?" + re.escape(end), lambda _: section, page, flags=re.S)
    else:
        page = page.rstrip("\n") + "\n\n" + section + "\n"
    with open(page_path, "w") as f:
        f.write(page)
