/* lmsname.c - a downloaded file's submission and own name (lmsname.h). */
#include "lmsname.h"

#include <stddef.h>
#include <stdio.h>
#include <string.h>

static bool digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Copies s[0 .. n-1] into out (LMS_NAME_MAX bytes); false if it does not fit. */
static bool copy(char *out, const char *s, size_t n)
{
    if (n >= LMS_NAME_MAX)
        return false;
    memcpy(out, s, n);
    out[n] = '\0';
    return true;
}

/* Canvas's "-N" before the extension of out->name taken off, when what is
 * left is a stage file's name (one of stages, with ".c"). */
static void canvas_again(LmsName *out, const char *const *stages, int nstages)
{
    char *dot = strrchr(out->name, '.');
    if (!dot)
        return;
    char *d = dot;
    while (d > out->name && digit(d[-1]))
        d--;
    if (d == dot || d - 1 <= out->name || d[-1] != '-' || dot - d > 4)
        return;
    char plain[LMS_NAME_MAX];
    snprintf(plain, sizeof plain, "%.*s%s", (int)(d - 1 - out->name), out->name, dot);
    for (int k = 0; k < nstages; k++) {
        size_t n = strlen(stages[k]);
        if (strncmp(plain, stages[k], n) == 0 && strcmp(plain + n, ".c") == 0) {
            int again = 0;
            for (const char *p = d; p < dot; p++)
                again = 10 * again + (*p - '0');
            out->again = again;
            memcpy(out->name, plain, strlen(plain) + 1);
            return;
        }
    }
}

/* After the student's part of a Canvas name, "_FILEID_FILE" at s: the
 * file's name, or NULL when s is not that. */
static const char *canvas_file(const char *s)
{
    if (*s != '_')
        return NULL;
    const char *f = s + 1;
    while (digit(*f))
        f++;
    return f == s + 1 || *f != '_' || f[1] == '\0' ? NULL : f + 1;
}

/* Fills *out for Canvas: who is the n bytes at w, file the file's name. */
static bool canvas_fill(LmsName *out, const char *w, size_t n, const char *file, bool late,
                        const char *const *stages, int nstages)
{
    if (!copy(out->who, w, n) || !copy(out->name, file, strlen(file)))
        return false;
    out->lms = LMS_CANVAS;
    out->late = late;
    canvas_again(out, stages, nstages);
    return true;
}

/* With anonymous grading: [LATE_]anon_ANONID_FILEID_FILE, ANONID letters
 * and digits (five, in base 58), in the path's last component. */
static bool canvas_anonymous(const char *base, const char *const *stages, int nstages, LmsName *out)
{
    bool late = strncmp(base, "LATE_", 5) == 0;
    const char *anon = late ? base + 5 : base;
    if (strncmp(anon, "anon_", 5) != 0)
        return false;
    const char *e = anon + 5;
    while ((*e >= 'A' && *e <= 'Z') || (*e >= 'a' && *e <= 'z') || digit(*e))
        e++;
    const char *file = e > anon + 5 ? canvas_file(e) : NULL;
    return file && canvas_fill(out, anon, (size_t)(e - anon), file, late, stages, nstages);
}

/* NAME_[LATE_]USERID_FILEID_FILE, in the path's last component. */
static bool canvas(const char *path, const char *const *stages, int nstages, LmsName *out)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (canvas_anonymous(base, stages, nstages, out))
        return true;
    for (const char *u = strchr(base, '_'); u; u = strchr(u + 1, '_')) {
        if (u == base)
            continue;
        const char *id = u + 1;
        bool late = strncmp(id, "LATE_", 5) == 0;
        if (late)
            id += 5;
        const char *e = id;
        while (digit(*e))
            e++;
        const char *file = e > id ? canvas_file(e) : NULL;
        if (!file)
            continue;
        char who[2 * LMS_NAME_MAX];
        snprintf(who, sizeof who, "%.*s_%.*s", (int)(u - base), base, (int)(e - id), id);
        return canvas_fill(out, who, strlen(who), file, late, stages, nstages);
    }
    return false;
}

/* FULL NAME_ID_assignsubmission_TYPE_/FILE or FULL NAME_ID_assignsubmission_TYPE_FILE. */
static bool moodle(const char *path, LmsName *out)
{
    static const char mark[] = "_assignsubmission_";
    const char *m = strstr(path, mark);
    if (!m || memchr(path, '/', (size_t)(m - path)))
        return false;
    const char *id = m;
    while (id > path && digit(id[-1]))
        id--;
    if (id == m || id - 1 <= path || id[-1] != '_')
        return false;                       /* no "_ID", or no name before it */
    const char *type = m + sizeof mark - 1, *t = type;
    while ((*t >= 'a' && *t <= 'z') || digit(*t))
        t++;
    if (t == type || *t != '_')
        return false;
    const char *file = t + 1;
    if (*file == '/')
        file++;                             /* the folder form */
    else if (strchr(file, '/'))
        return false;
    if (*file == '\0' || file[strlen(file) - 1] == '/')
        return false;
    if (!copy(out->who, path, (size_t)(m - path)) || !copy(out->name, file, strlen(file)))
        return false;
    out->lms = LMS_MOODLE;
    return true;
}

/* ASSIGNMENT_USERNAME_attempt_DATE_FILE or ASSIGNMENT_USERNAME_attempt_
 * DATE.txt, in the path's last component. */
static bool blackboard(const char *path, LmsName *out)
{
    static const char mark[] = "_attempt_";
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    for (const char *m = strstr(base, mark); m; m = strstr(m + 1, mark)) {
        const char *user = m;
        while (user > base && user[-1] != '_')
            user--;
        if (user == m || user - 1 <= base)
            continue;                       /* no username, or no assignment before it */
        const char *date = m + sizeof mark - 1, *e = date;
        int digits = 0;
        while (digit(*e) || *e == '-')
            digits += digit(*e++);
        if (digits < 8 || e - date >= (ptrdiff_t)sizeof out->attempt)
            continue;
        char receipt[sizeof out->attempt + 16];
        snprintf(receipt, sizeof receipt, "attempt_%.*s.txt", (int)(e - date), date);
        const char *name = *e == '_' && e[1] != '\0' ? e + 1 : strcmp(e, ".txt") == 0 ? receipt : NULL;
        if (!name)
            continue;
        if (!copy(out->who, user, (size_t)(m - user)) || !copy(out->name, name, strlen(name)))
            return false;
        memcpy(out->attempt, date, (size_t)(e - date));
        out->attempt[e - date] = '\0';
        out->user_at = (size_t)(user - base);
        out->lms = LMS_BLACKBOARD;
        return true;
    }
    return false;
}

/* Each reader sets only the fields its platform has: late, again, attempt
 * and user_at stay 0 or empty otherwise. */
bool lms_name(const char *path, const char *const *stages, int nstages, LmsName *out)
{
    memset(out, 0, sizeof *out);
    return moodle(path, out) || blackboard(path, out) || canvas(path, stages, nstages, out);
}
