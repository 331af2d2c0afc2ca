/*
 * memo.h - compiling each distinct stage file once in a grade --all run.
 *
 * In a class, many submissions hold the same file: a part left as the
 * skeleton, a copy of the handout's code, and in the kit's own self-test
 * the reference beside one faulty file.  grade --all, as root only, makes
 * a directory that only root can enter and passes it to each submission's
 * grading; a stage file's object, the compiler's messages about it and,
 * loaded, its shared object are kept there after they built, and a later
 * file of the same stage with the same bytes (compared whole, not by a
 * hash) uses them instead of compiling again.  Not as another user: there
 * the students' code may run as that user and could change what is kept.
 */
#ifndef MEMO_H
#define MEMO_H

#include <stdbool.h>
#include <stddef.h>

/* An entry: the directory of what is kept for one file's bytes. */
typedef struct {
    char dir[1024];            /* "" when there is none                     */
    bool found;                /* it was there (else it was just made)      */
} MemoEntry;

/* Finds the entry for the source file src of stage (kind: "o" or "pic"),
 * or makes an empty one; false when memo is NULL or nothing can be kept. */
bool memo_find(const char *memo, const char *stage, const char *kind, const char *src,
               MemoEntry *e);

/* For an entry that was found (e->found): waits until the grading that
 * made it has finished compiling its file, at most seconds; true when the
 * object is there to use, false when that compile did not keep one (the
 * file did not build, or it was not done in time): then compile it again.
 * The maker marks the end with memo_keep_text(e, "done", ""). */
bool memo_wait(const MemoEntry *e, double seconds);

/* The path of name in the entry (object.o, messages, student.so). */
void memo_path(const MemoEntry *e, const char *name, char *path, size_t len);

/* Keeps a copy of file as name in the entry; 0 on success.  The copy is
 * written under another name and renamed, so that a reader sees all of it
 * or nothing. */
int memo_keep(const MemoEntry *e, const char *name, const char *file);

/* Keeps text as name in the entry; 0 on success. */
int memo_keep_text(const MemoEntry *e, const char *name, const char *text);

/* Counts a use of the entry: a byte more in its file "uses". */
void memo_use(const MemoEntry *e);

/* The text kept as name (malloc'd), or NULL. */
char *memo_read_text(const MemoEntry *e, const char *name);

#endif
