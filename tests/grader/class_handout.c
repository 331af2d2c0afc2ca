/*
 * class_handout.c - whether a cause is one of the mistakes a part's
 * handout lists.  Each handout of Parts 1-3b (handouts/<stage>.md) has a
 * table of its mistakes whose last column, "what went wrong starts", gives
 * the start of the sentence the grader writes for each, in backquotes:
 *
 *     | mistake | what the picture does | what went wrong starts |
 *     | tan of degrees (above) | magnified, turned half a turn | `tan was given the angle in degrees` |
 *
 * A cause whose sentence begins with one of those is that row's mistake.
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "class_model.h"
#include "build.h"
#include "kit/savefile.h"

#include <stdlib.h>
#include <string.h>

/* The next cell of a table's row at *s (after a "|"), to the next "|" not
 * written "\|": its start, and its length in *n; *s moves past it. */
static const char *next_cell(const char **s, size_t *n)
{
    const char *start = *s, *p = start;
    while (*p && *p != '\n' && !(*p == '|' && (p == start || p[-1] != '\\')))
        p++;
    *n = (size_t)(p - start);
    *s = *p == '|' ? p + 1 : p;
    return start;
}

/* Whether one of the `...` of cell[0 .. n) begins text. */
static bool cell_begins(const char *cell, size_t n, const char *text)
{
    for (const char *end = cell + n, *q = memchr(cell, '`', n); q && q < end;) {
        const char *close = memchr(q + 1, '`', (size_t)(end - q - 1));
        if (!close)
            return false;
        size_t len = (size_t)(close - q - 1);
        if (len > 0 && strncmp(text, q + 1, len) == 0)
            return true;
        q = close + 1 < end ? memchr(close + 1, '`', (size_t)(end - close - 1)) : NULL;
    }
    return false;
}

/* The row at line, when it is a mistake's and its last cell begins text:
 * its first cell, less " (above)" and its backquotes, into mistake. */
static bool row_lists(const char *line, const char *text, char *mistake, size_t n)
{
    const char *s = line + 1, *first = NULL, *last = NULL;
    size_t nfirst = 0, nlast = 0, len;
    while (*s && *s != '\n') {
        const char *cell = next_cell(&s, &len);
        if (!first) {
            first = cell;
            nfirst = len;
        } else if (strspn(cell, " ") < len) {
            last = cell;
            nlast = len;
        }
    }
    if (!last || !cell_begins(last, nlast, text))
        return false;
    while (nfirst > 0 && first[0] == ' ')
        first++, nfirst--;
    while (nfirst > 0 && first[nfirst - 1] == ' ')
        nfirst--;
    if (nfirst > 8 && strncmp(first + nfirst - 8, " (above)", 8) == 0)
        nfirst -= 8;
    size_t used = 0;                    /* the cell as it reads: no backquotes */
    for (size_t k = 0; k < nfirst && used + 1 < n; k++)
        if (first[k] != '`')
            mistake[used++] = first[k];
    if (n > 0)
        mistake[used] = '\0';
    return true;
}

bool class_handout_lists(int part, const char *text, char *mistake, size_t n)
{
    char path[128];
    size_t len;
    snprintf(path, sizeof path, "handouts/%s.md", stage_names[part]);
    char *md = kit_load_file(path, 1u << 20, &len);
    bool in_table = false, found = false;
    for (const char *line = md; line && *line && !found;) {
        if (line[0] != '|')
            in_table = false;
        else if (!in_table)
            in_table = strstr(line, "what went wrong starts") &&
                       strstr(line, "what went wrong starts") < line + strcspn(line, "\n");
        else if (strncmp(line, "|---", 4) != 0)
            found = row_lists(line, text, mistake, n);
        const char *nl = strchr(line, '\n');
        line = nl ? nl + 1 : NULL;
    }
    free(md);
    return found;
}
