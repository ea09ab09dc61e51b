/*
 * terminal_key.c: one key read out of line mode. See terminal_key.h.
 */
#include "terminal_key.h"

#include <termios.h>
#include <unistd.h>

int terminal_read_key(int fd)
{
    struct termios was, key;
    int changed = tcgetattr(fd, &was) == 0;
    if (changed) {
        key = was;
        key.c_lflag &= ~(tcflag_t)ICANON;
        key.c_cc[VMIN] = 1;
        key.c_cc[VTIME] = 0;
        changed = tcsetattr(fd, TCSANOW, &key) == 0;
    }
    unsigned char byte;
    ssize_t got = read(fd, &byte, 1);
    if (changed)
        tcsetattr(fd, TCSANOW, &was);
    return got == 1 ? byte : -1;
}
