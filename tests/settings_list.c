/* settings_list.c - print the settings table, for the man page check. */
#include <stdio.h>

#include "scene.h"

int
main(void)
{
	scene_settings_list(stdout);
	return fflush(stdout) != 0;
}
