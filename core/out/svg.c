/*
 * svg.c: SVG documents, numbers, escaping and the export palette. See
 * svg.h.
 */
#include "core/out/svg.h"

#include <math.h>
#include <stdarg.h>
#include <string.h>

void svg_begin(struct svg *svg, FILE *out, double width, double height,
               int precision)
{
    svg->out = out;
    svg->precision = precision < 0 ? 0 : precision > 9 ? 9 : precision;
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"", out);
    svg_attribute(svg, "width", width);
    svg_attribute(svg, "height", height);
    fputs(" viewBox=\"0 0 ", out);
    svg_number(svg, width);
    fputc(' ', out);
    svg_number(svg, height);
    fputs("\" font-family=\"sans-serif\" font-size=\"12\">\n", out);
}

void svg_end(struct svg *svg)
{
    fputs("</svg>\n", svg->out);
}

void svg_format_number(char *text, size_t size, double x, int precision)
{
    if (size == 0)
        return;
    if (!isfinite(x))
        x = 0;
    int n = snprintf(text, size, "%.*f", precision, x);
    if (n < 0 || (size_t)n >= size) {
        /* Too wide for the buffer: fall back to a short general form. */
        snprintf(text, size, "%.6g", x);
        return;
    }
    char *point = strchr(text, '.');
    if (point != NULL) {
        char *end = text + n;
        while (end > point + 1 && end[-1] == '0')
            *--end = '\0';
        if (end == point + 1)
            *point = '\0';
    }
    if (strcmp(text, "-0") == 0)
        strcpy(text, "0");
}

void svg_number(struct svg *svg, double x)
{
    char text[64];
    svg_format_number(text, sizeof text, x, svg->precision);
    fputs(text, svg->out);
}

void svg_attribute(struct svg *svg, const char *name, double x)
{
    fprintf(svg->out, " %s=\"", name);
    svg_number(svg, x);
    fputc('"', svg->out);
}

/* The length of the valid UTF-8 sequence at s, or 0 when it is not one
 * (overlong forms, surrogates and code points past U+10FFFF included). */
static int utf8_length(const unsigned char *s)
{
    if (s[0] < 0x80)
        return 1;
    int n;
    unsigned int code;
    if ((s[0] & 0xe0) == 0xc0) {
        n = 2;
        code = s[0] & 0x1f;
    } else if ((s[0] & 0xf0) == 0xe0) {
        n = 3;
        code = s[0] & 0x0f;
    } else if ((s[0] & 0xf8) == 0xf0) {
        n = 4;
        code = s[0] & 0x07;
    } else {
        return 0;
    }
    for (int k = 1; k < n; k++) {
        if ((s[k] & 0xc0) != 0x80)
            return 0;
        code = (code << 6) | (s[k] & 0x3f);
    }
    static const unsigned int least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < least[n] || code > 0x10ffff ||
        (code >= 0xd800 && code <= 0xdfff) || code == 0xfffe ||
        code == 0xffff)
        return 0;
    return n;
}

void svg_escape(FILE *out, const char *text)
{
    const unsigned char *s = (const unsigned char *)text;
    while (*s) {
        switch (*s) {
        case '&': fputs("&amp;", out); s++; continue;
        case '<': fputs("&lt;", out); s++; continue;
        case '>': fputs("&gt;", out); s++; continue;
        case '"': fputs("&quot;", out); s++; continue;
        case '\'': fputs("&apos;", out); s++; continue;
        default: break;
        }
        if (*s < 0x20 && *s != '\t' && *s != '\n' && *s != '\r') {
            fputc('?', out);
            s++;
            continue;
        }
        int n = utf8_length(s);
        if (n == 0) {
            fputc('?', out);
            s++;
            continue;
        }
        fwrite(s, 1, (size_t)n, out);
        s += n;
    }
}

void svg_text(struct svg *svg, double x, double y, const char *attributes,
              const char *format, ...)
{
    char text[512];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    fputs("<text", svg->out);
    svg_attribute(svg, "x", x);
    svg_attribute(svg, "y", y);
    if (attributes != NULL && attributes[0] != '\0')
        fprintf(svg->out, " %s", attributes);
    fputc('>', svg->out);
    svg_escape(svg->out, text);
    fputs("</text>\n", svg->out);
}

/* The caller's attributes, if any, and the end of an empty element. */
static void end_element(struct svg *svg, const char *attributes)
{
    if (attributes != NULL && attributes[0] != '\0')
        fprintf(svg->out, " %s", attributes);
    fputs("/>\n", svg->out);
}

void svg_rect(struct svg *svg, double x, double y, double width,
              double height, const char *attributes)
{
    fputs("<rect", svg->out);
    svg_attribute(svg, "x", x);
    svg_attribute(svg, "y", y);
    svg_attribute(svg, "width", width);
    svg_attribute(svg, "height", height);
    end_element(svg, attributes);
}

void svg_line(struct svg *svg, double x1, double y1, double x2, double y2,
              const char *attributes)
{
    fputs("<line", svg->out);
    svg_attribute(svg, "x1", x1);
    svg_attribute(svg, "y1", y1);
    svg_attribute(svg, "x2", x2);
    svg_attribute(svg, "y2", y2);
    end_element(svg, attributes);
}

void svg_point(struct svg *svg, double x, double y)
{
    svg_number(svg, x);
    fputc(',', svg->out);
    svg_number(svg, y);
}

/* One table, so that a picture and an OBJ of the same option agree.
 * Okabe and Ito's colours, which readers with any common colour vision
 * deficiency tell apart (test_export measures them under simulated
 * protanopia, deuteranopia and tritanopia): never red against green. */
static const char *const type_colour[TYPE_COUNT] = {
    "#0072b2",  /* FP: blue */
    "#f0e442",  /* SP: yellow */
    "#d55e00",  /* DP: vermillion */
};

static const char *const class_colour[CLASS_COUNT] = {
    "#56b4e9",  /* convex feature curve: sky blue */
    "#999999",  /* saddle: grey */
    "#009e73",  /* concave feature curve: bluish green */
    "#f0e442",  /* ruled convex: SP's yellow */
    "#0072b2",  /* flat: FP's blue */
    "#e69f00",  /* ruled concave: orange */
    "#d55e00",  /* convex round: DP's vermillion */
    "#cc79a7",  /* concave round: reddish purple */
};

const char *svg_type_colour(enum panel_type type)
{
    return (unsigned)type < TYPE_COUNT ? type_colour[type] : "#888888";
}

const char *svg_class_colour(enum panel_class class)
{
    return (unsigned)class < CLASS_COUNT ? class_colour[class] : "#888888";
}
