/*
 * config.c - reading tests/weights.conf (see the comments in that file).
 */
#define _POSIX_C_SOURCE 200809L
#define _DARWIN_C_SOURCE        /* macOS: the rest too (mkdtemp, _SC_NPROCESSORS_ONLN...) */
#include "config.h"
#include "kit/textfile.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* "parts 1 2 3a 3b 4 5": the labels after the keyword, each known and
 * given once; true and parts set, or false. */
static bool parse_parts(const char *line, bool parts[NPARTS])
{
    bool seen[NPARTS] = { false };
    char label[8];
    int used = 0, count = 0;
    if (sscanf(line, " parts%n", &used) != 0 || used == 0)
        return false;
    line += used;
    while (sscanf(line, " %7s%n", label, &used) == 1) {
        int p = part_from_label(label);
        if (p < 0 || seen[p])
            return false;
        seen[p] = true;
        count++;
        line += used;
    }
    if (count == 0)
        return false;
    for (int p = 0; p < NPARTS; p++)
        parts[p] = seen[p];
    return true;
}

/* "KEY A" or "KEY B" alone on the line (its keyword already read):
 * true, with *first set when it is A; false otherwise. */
static bool either_word(const char *line, const char *a, const char *b, bool *first)
{
    char key[32], mode[16];
    int used = 0;
    if (sscanf(line, " %31s %15s %n", key, mode, &used) != 2 || used == 0 || line[used] ||
        (strcmp(mode, a) != 0 && strcmp(mode, b) != 0))
        return false;
    *first = strcmp(mode, a) == 0;
    return true;
}

/* Whether line is "KEY S" with S seconds, more than 0 and at most max:
 * true, with *seconds set; false otherwise. */
static bool seconds_word(const char *line, double max, double *seconds)
{
    char key[32];
    double s = 0;
    int used = 0;
    if (sscanf(line, " %31s %lf %n", key, &s, &used) != 2 || used == 0 || line[used] || !(s > 0 && s <= max))
        return false;
    *seconds = s;
    return true;
}

/* A setting, its keyword word the line's first: NULL when it is read into
 * cfg, else what was expected (in wanted, of size n, when it is made up). */
static const char *read_setting(GradeConfig *cfg, const char *line, const char *word, char *wanted, size_t n)
{
    char label[8];
    double x = 0, hard = 0;
    unsigned long long seed = 0;
    long kib = 0;
    int used = 0;               /* where the line's words ended: only blanks may follow */
    if (strcmp(word, "part") == 0) {
        if (sscanf(line, " part %7s core %lf hard %lf %n", label, &x, &hard, &used) != 3 || used == 0 ||
            line[used] || part_from_label(label) < 0 || x < 0 || hard < 0 || !isfinite(x + hard))
            return "'part P core N hard M': P one of 1 2 3a 3b 4 5, N and M points, 0 or more";
        cfg->core[part_from_label(label)] = x;
        cfg->hard[part_from_label(label)] = hard;
    } else if (strcmp(word, "hard") == 0) {
        if (!either_word(line, "bonus", "core", &cfg->hard_is_bonus))
            return "'hard bonus' or 'hard core'";
    } else if (strcmp(word, "hints") == 0) {
        bool challenge;
        if (!either_word(line, "challenge", "full", &challenge))
            return "'hints challenge' or 'hints full'";
        cfg->full_hints = !challenge;
    } else if (strcmp(word, "timeout") == 0) {
        if (!seconds_word(line, 600, &cfg->timeout))
            return "'timeout S': S seconds, more than 0 and at most 600";
    } else if (strcmp(word, "part-time") == 0) {
        if (!seconds_word(line, 3600, &cfg->part_time))
            return "'part-time S': S seconds, more than 0 and at most 3600";
    } else if (strcmp(word, "output") == 0) {
        if (sscanf(line, " output %ld %n", &kib, &used) != 1 || used == 0 || line[used] || kib < 1 ||
            kib > CONFIG_OUTPUT_KIB_MAX) {
            snprintf(wanted, n, "'output KIB': KIB a whole number of KiB from 1 to %d", CONFIG_OUTPUT_KIB_MAX);
            return wanted;
        }
        cfg->output_kib = kib;
    } else if (strcmp(word, "seed") == 0) {
        if (sscanf(line, " seed %llu %n", &seed, &used) != 1 || used == 0 || line[used] || strchr(line, '-'))
            return "'seed N': N a whole number, 0 or more";
        cfg->seed = seed;
    } else if (strcmp(word, "parts") == 0) {
        if (!parse_parts(line, cfg->parts))
            return "'parts P...': each of 1 2 3a 3b 4 5 at most once";
    } else {
        return "'part P core N hard M', 'parts P...', 'hard bonus|core', 'hints challenge|full', "
               "'timeout S', 'part-time S', 'output KIB' or 'seed N'";
    }
    return NULL;
}

int config_read(GradeConfig *cfg, const char *path, char *err, size_t errlen)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->hard_is_bonus = true;
    cfg->timeout = 2;
    cfg->part_time = 30;
    cfg->output_kib = CONFIG_OUTPUT_KIB;
    for (int p = 0; p < NCORE_PARTS; p++)
        cfg->parts[p] = true;
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    char line[512], word[32], wanted[100];
    const char *want = NULL;
    for (int lineno = 1; !want && fgets(line, sizeof line, f); lineno++) {
        /* A line longer than the buffer: the rest of a comment is skipped;
         * a setting that long is refused rather than read as two lines. */
        if (!strchr(line, '\n') && !feof(f)) {
            int c;
            while ((c = getc(f)) != EOF && c != '\n')
                ;
            if (!strchr(line, '#')) {
                snprintf(wanted, sizeof wanted, "the line is longer than %d characters", (int)sizeof line - 2);
                want = wanted;
            }
        }
        size_t bom = lineno == 1 ? text_bom_length(line, strlen(line)) : 0;
        if (bom)
            memmove(line, line + bom, strlen(line + bom) + 1);      /* not text */
        line[strcspn(line, "#")] = '\0';
        if (!want && sscanf(line, "%31s", word) == 1 && (want = read_setting(cfg, line, word, wanted, sizeof wanted)))
            snprintf(err, errlen, "%s:%d: expected %s", path, lineno, want);
        else if (want)
            snprintf(err, errlen, "%s:%d: %s", path, lineno, want);
    }
    fclose(f);
    return want ? -1 : 0;
}
