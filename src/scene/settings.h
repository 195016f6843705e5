/*
 * settings.h - the settings every scene has (settings.c): the top
 * level's table is scene.h's, the organs entries' is here; and every
 * table of the program listed, for the test that checks the man page.
 */
#ifndef SETTINGS_H
#define SETTINGS_H

#include <stdio.h>

#include "base/table.h"

/* The tables, one setting a line, for the test that checks the man page. */
void	settings_list(FILE *);
/* The rows of an organs entry. */
extern const struct table range_table;

#endif
