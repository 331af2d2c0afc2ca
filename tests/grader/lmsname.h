/*
 * lmsname.h - the names a learning platform gives a class's files when it
 * downloads them all at once, read back: whose submission a file is, and
 * the name its student gave it.
 *
 *   Canvas ("Download Submissions"): one zip of every student's files,
 *   each renamed NAME_USERID_FILEID_FILE, or NAME_LATE_USERID_FILEID_FILE
 *   when it came late (USERID and FILEID digits: the user's and the
 *   uploaded file's); with anonymous grading, anon_ANONID_FILEID_FILE or
 *   LATE_anon_ANONID_FILEID_FILE (ANONID five letters and digits, the
 *   submission's anonymous id).  A file the student uploaded again under
 *   the same name gets "-N" before its extension ("part1_image_plane-1.c").
 *
 *   Blackboard Learn ("Assignment File Download"): one zip of every
 *   student's files, each renamed ASSIGNMENT_USERNAME_attempt_DATE_FILE
 *   (DATE as 2024-03-15-10-30-00: the attempt's), beside a text file of
 *   the attempt's own, ASSIGNMENT_USERNAME_attempt_DATE.txt; with every
 *   attempt downloaded, a student's earlier attempts are there too.
 *
 *   Moodle ("Download all submissions"): each student's files in a folder
 *   FULL NAME_ID_assignsubmission_file_ (the default since Moodle 3.1), or,
 *   with folders turned off, each file named FULL NAME_ID_assignsubmission_
 *   file_FILE (ID digits; the plugin's name, "file", may be another).
 *
 * sortsubs (make sort-submissions) sorts such a download into one folder
 * per submission, as grade --all takes them; grade --all names the command
 * when it is given such a download.  (Blackboard's form is read as the
 * tools that sort its downloads read it, BBGradebookOrganiser among them:
 * the username is what comes between the last "_" before "_attempt_" and
 * it, the file's own name what follows the date.  A username may hold "_"
 * too: sortsubs takes the name of the assignment, which a download's files
 * share, for the rest.)
 */
#ifndef GRADER_LMSNAME_H
#define GRADER_LMSNAME_H

#include <stdbool.h>
#include <stddef.h>

typedef enum { LMS_CANVAS = 1, LMS_MOODLE, LMS_BLACKBOARD } Lms;

#define LMS_NAME_MAX 256

typedef struct {
    Lms lms;
    char who[LMS_NAME_MAX];   /* the submission's folder: "smithbob_340934"
                                 (Canvas: name and user id), "anon_Xy3Ab"
                                 (Canvas, anonymous), "Ann Lee_123456"
                                 (Moodle: full name and participant id),
                                 "jsmith" (Blackboard: the username)        */
    char name[LMS_NAME_MAX];  /* the file as its student named it; for
                                 Blackboard's text file of an attempt,
                                 "attempt_DATE.txt"                         */
    char attempt[32];         /* Blackboard: the attempt's DATE; else ""    */
    size_t user_at;           /* Blackboard: where who begins in the path's
                                 last component; else 0                     */
    int again;                /* Canvas's "-N" taken off name: N; else 0     */
    bool late;                /* Canvas's LATE mark                          */
} LmsName;

/* Reads path, a file's path in a download (relative, '/'-separated), into
 * *out; true when it is named as one of the two platforms name a file of a
 * submission, false (and *out unspecified) otherwise.  stages lists the
 * stage files' names without ".c" ("part1_image_plane", ...: build.h's
 * stage_names), nstages of them: a Canvas "-N" is taken off only where
 * that leaves one of them with ".c", so that a student's own "notes-2.txt"
 * keeps its name. */
bool lms_name(const char *path, const char *const *stages, int nstages, LmsName *out);

#endif
