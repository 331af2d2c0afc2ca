/*
 * config.c - reading tests/weights.conf (see the comments in that file).
 */
#define _POSIX_C_SOURCE 200809L
#include "config.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int config_read(GradeConfig *cfg, const char *path, char *err, size_t errlen)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->hard_is_bonus = true;
    cfg->timeout = 2;
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    char line[512];
    int lineno = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        line[strcspn(line, "#")] = '\0';
        char word[32], label[8], mode[16];
        double core, hard;
        unsigned long long seed;
        if (sscanf(line, "%31s", word) != 1)
            continue;
        if (strcmp(word, "part") == 0 &&
            sscanf(line, " part %7s core %lf hard %lf", label, &core, &hard) == 3 &&
            part_from_label(label) >= 0 && core >= 0 && hard >= 0 && isfinite(core + hard)) {
            cfg->core[part_from_label(label)] = core;
            cfg->hard[part_from_label(label)] = hard;
        } else if (strcmp(word, "hard") == 0 && sscanf(line, " hard %15s", mode) == 1 &&
                   (!strcmp(mode, "bonus") || !strcmp(mode, "core"))) {
            cfg->hard_is_bonus = strcmp(mode, "bonus") == 0;
        } else if (strcmp(word, "timeout") == 0 && sscanf(line, " timeout %lf", &core) == 1 &&
                   core > 0 && core <= 600) {
            cfg->timeout = core;
        } else if (strcmp(word, "seed") == 0 && sscanf(line, " seed %llu", &seed) == 1) {
            cfg->seed = seed;
        } else {
            snprintf(err, errlen, "%s:%d: expected 'part P core N hard M', 'hard bonus|core', "
                     "'timeout S' or 'seed N'", path, lineno);
            fclose(f);
            return -1;
        }
    }
    fclose(f);
    return 0;
}
