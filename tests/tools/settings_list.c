/* settings_list.c - print the settings table, for the man page check. */
#include <stdio.h>

#include "scene/settings.h"

int
main(void)
{
	settings_list(stdout);
	return fflush(stdout) != 0;
}
