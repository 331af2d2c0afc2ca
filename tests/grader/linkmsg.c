/*
 * linkmsg.c - see linkmsg.h.
 */
#include "linkmsg.h"
#include "contract.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Adds the n bytes at name to names unless there already, or too long. */
static void add(char names[][LINKMSG_NAME_MAX], int *count, int max, const char *name, size_t n)
{
    if (*count >= max || n == 0 || n >= LINKMSG_NAME_MAX)
        return;
    for (int k = 0; k < *count; k++)
        if (strncmp(names[k], name, n) == 0 && names[k][n] == '\0')
            return;
    memcpy(names[*count], name, n);
    names[(*count)++][n] = '\0';
}

/* Whether c may be part of a C identifier. */
static bool word_char(char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/* The identifier at p: its length (0 when none). */
static size_t identifier(const char *p)
{
    size_t n = 0;
    while (word_char(p[n]))
        n++;
    return n;
}

/* The name a line of a linker's message says is undefined (dup false) or
 * defined twice (dup true): its start in *name, its length returned; 0 when the
 * line says neither. */
static size_t line_name(const char *copy, bool dup, const char **name)
{
    const char *at;
    const char *word = dup ? "multiple definition of " : "undefined reference to ";
    size_t wn = strlen(word);
    if ((at = strstr(copy, word)) && (at[wn] == '`' || at[wn] == '\'')) {   /* GNU ld, gold */
        at += wn + 1;
        const char *q = strchr(at, '\'');
        *name = at;
        return q && identifier(at) == (size_t)(q - at) ? (size_t)(q - at) : 0;
    }
    if (!dup && (at = strstr(copy, "undefined symbol: "))) {                  /* lld */
        *name = at + strlen("undefined symbol: ");
        return identifier(*name);
    }
    if (dup && (at = strstr(copy, "duplicate symbol: "))) {                   /* lld */
        *name = at + strlen("duplicate symbol: ");
        return identifier(*name);
    }
    if (!dup && (at = strstr(copy, "\", referenced from"))) {                /* Apple's ld */
        const char *q = at;
        while (q > copy && q[-1] != '"')
            q--;
        *name = q + 1;
        return q > copy && *q == '_' && identifier(q) == (size_t)(at - q) ? (size_t)(at - q - 1) : 0;
    }
    if (dup && (at = strstr(copy, "duplicate symbol "))) {                    /* Apple's ld */
        at += strlen("duplicate symbol ");
        bool quoted = *at == '\'';
        at += quoted;
        size_t n = identifier(at);
        const char *after = at + n;
        if (quoted && *after++ != '\'')
            return 0;
        *name = at + 1;
        return *at == '_' && n > 1 && strncmp(after, " in:", 4) == 0 ? n - 1 : 0;
    }
    return 0;
}

static int names_in(const char *text, bool dup, char names[][LINKMSG_NAME_MAX], int max)
{
    int count = 0;
    for (const char *line = text; line && *line && count < max;) {
        const char *end = strchr(line, '\n');
        size_t len = end ? (size_t)(end - line) : strlen(line);
        char copy[512];
        size_t n = len < sizeof copy - 1 ? len : sizeof copy - 1;
        memcpy(copy, line, n);
        copy[n] = '\0';
        const char *name = NULL;
        size_t nn = line_name(copy, dup, &name);
        if (nn)
            add(names, &count, max, name, nn);
        line = end ? end + 1 : NULL;
    }
    return count;
}

int linkmsg_undefined(const char *text, char names[][LINKMSG_NAME_MAX], int max)
{
    return names_in(text, false, names, max);
}

int linkmsg_duplicate(const char *text, char names[][LINKMSG_NAME_MAX], int max)
{
    return names_in(text, true, names, max);
}

static bool space(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

/* The directive on the line at p (after its blanks, '#', blanks), or NULL
 * when the line is not one; *n its name's length. */
static const char *directive(const char *p, size_t *n)
{
    while (*p == ' ' || *p == '\t')
        p++;
    if (*p != '#')
        return NULL;
    p++;
    while (*p == ' ' || *p == '\t')
        p++;
    *n = identifier(p);
    return p;
}

/* Turns into spaces, in s (comments already gone), each group under "#if
 * 0" up to its #else, #elif or #endif (the directives nested in it
 * counted), so that a definition kept there as an old version is not read
 * as code. */
static void blank_if0(char *s)
{
    int depth = -1;                     /* -1: not in a group under #if 0 */
    for (char *line = s; *line;) {
        char *nl = strchr(line, '\n'), *end = nl ? nl : line + strlen(line);
        size_t n;
        const char *d = directive(line, &n);
        bool blank = depth >= 0;
        if (d && depth < 0 && n == 2 && strncmp(d, "if", 2) == 0) {
            const char *v = d + 2;
            while (*v == ' ' || *v == '\t')
                v++;
            if (v[0] == '0' && !word_char(v[1])) {
                const char *rest = v + 1;
                while (rest < end && space(*rest))
                    rest++;
                if (rest == end)
                    depth = 0;
            }
        } else if (d && depth >= 0) {
            if (n >= 2 && strncmp(d, "if", 2) == 0)
                depth++;
            else if (n == 5 && strncmp(d, "endif", 5) == 0)
                depth--;
            else if (depth == 0 && ((n == 4 && strncmp(d, "else", 4) == 0) ||
                                    (n == 4 && strncmp(d, "elif", 4) == 0)))
                depth = -1;
        }
        if (blank)
            memset(line, ' ', (size_t)(end - line));
        line = nl ? nl + 1 : end;
    }
}

/* A copy of text with its comments, its string and character literals
 * and its groups under "#if 0" turned into spaces (newlines kept), so that
 * a definition commented out, or a name in a message, is not read as
 * code; NULL when out of memory. */
static char *code_only(const char *text)
{
    size_t n = strlen(text);
    char *s = malloc(n + 1);
    if (!s)
        return NULL;
    memcpy(s, text, n + 1);
    for (size_t k = 0; k < n;) {
        size_t end = k + 1;
        if (s[k] == '/' && s[k + 1] == '*') {
            const char *close = strstr(s + k + 2, "*/");
            end = close ? (size_t)(close - s) + 2 : n;
        } else if (s[k] == '/' && s[k + 1] == '/') {
            const char *nl = strchr(s + k, '\n');
            end = nl ? (size_t)(nl - s) : n;
        } else if (s[k] == '"' || s[k] == '\'') {
            for (end = k + 1; end < n && s[end] != s[k] && s[end] != '\n'; end++)
                end += s[end] == '\\' && end + 1 < n;
            end += end < n && s[end] == s[k];
        } else {
            k++;
            continue;
        }
        for (; k < end; k++)
            if (s[k] != '\n')
                s[k] = ' ';
    }
    blank_if0(s);
    return s;
}

/* Whether the n-character identifier at p, in text, starts a definition:
 * its parameters in parentheses, then a body's "{". */
static bool defined_at(const char *text, const char *p, size_t n)
{
    static const char *const statements[] = { "if", "for", "while", "switch", "return", "sizeof" };
    if ((p > text && word_char(p[-1])) || word_char(p[n]) || (*p >= '0' && *p <= '9'))
        return false;
    for (size_t k = 0; k < sizeof statements / sizeof statements[0]; k++)
        if (strlen(statements[k]) == n && strncmp(p, statements[k], n) == 0)
            return false;
    const char *q = p + n;
    while (space(*q))
        q++;
    if (*q != '(')
        return false;
    int depth = 0;
    for (; *q; q++) {
        depth += (*q == '(') - (*q == ')');
        if (depth == 0)
            break;
    }
    if (!*q)
        return false;
    for (q++; space(*q); q++)
        ;
    return *q == '{';
}

bool linkmsg_defines(const char *text, const char *name)
{
    char *code = code_only(text);
    const char *s = code ? code : text;
    size_t n = strlen(name);
    bool found = false;
    for (const char *p = strstr(s, name); p && n && !found; p = strstr(p + 1, name))
        found = defined_at(s, p, n);
    free(code);
    return found;
}

int linkmsg_definitions(const char *text, char names[][LINKMSG_NAME_MAX], int max)
{
    char *code = code_only(text);
    const char *s = code ? code : text;
    int count = 0;
    for (const char *p = s; *p && count < max;) {
        size_t n = identifier(p);
        if (n == 0) {
            p++;
            continue;
        }
        if (defined_at(s, p, n))
            add(names, &count, max, p, n);
        p += n;
    }
    free(code);
    return count;
}

void linkmsg_definitions_list(const char *text, char *out, size_t n)
{
    char names[8][LINKMSG_NAME_MAX];
    int count = linkmsg_definitions(text, names, 8);
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < count && used < n; k++)
        used += (size_t)snprintf(out + used, n - used, "%s%s", k == 0 ? "" : k == count - 1 ? " and " : ", ",
                                 names[k]);
    if (count == 0)
        snprintf(out, n, "none");
}

const char *linkmsg_stage_of(const char *name)
{
    static const char *const stages[] = { CONTRACT_STAGE_NAMES };
    static const struct {
        const char *name;
        int part;
    } contract[] = {
#define ROW(function, part) { #function, part },
        CONTRACT_FUNCTIONS(ROW)
#undef ROW
    };
    for (size_t k = 0; k < sizeof contract / sizeof contract[0]; k++)
        if (strcmp(contract[k].name, name) == 0)
            return stages[contract[k].part];
    return NULL;
}
