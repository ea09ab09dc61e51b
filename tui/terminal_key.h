/*
 * terminal_key.h: one key read from a terminal before curses starts, for
 * a question answered by a key, as "(y/n)" promises.
 */
#ifndef FACET_TERMINAL_KEY_H
#define FACET_TERMINAL_KEY_H

/* Reads one byte from the terminal fd with its line mode off for that
 * read (the key echoes; Ctrl-C still interrupts), and puts the terminal
 * back as it was. Returns the byte, or -1 at end of input or on an error.
 * A file descriptor that is no terminal is read as it is: up to the byte. */
int terminal_read_key(int fd);

#endif
