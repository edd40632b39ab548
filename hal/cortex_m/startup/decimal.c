#include "startup/decimal.h"

char *spanlight_format_decimal(uint32_t value, char *out) {
  char reversed[10];
  int count = 0;
  do {
    reversed[count++] = (char)('0' + value % 10u);
    value /= 10u;
  } while (value != 0u);
  char *cursor = out;
  while (count > 0) {
    *cursor++ = reversed[--count];
  }
  *cursor = '\0';
  return out;
}

char *spanlight_format_hex(uint32_t value, char *out) {
  static const char digits[] = "0123456789abcdef";
  out[0] = '0';
  out[1] = 'x';
  for (int i = 0; i < 8; ++i) {
    out[2 + i] = digits[(value >> (28 - 4 * i)) & 0xFu];
  }
  out[10] = '\0';
  return out;
}
