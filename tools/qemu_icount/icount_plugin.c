/* spanlight_icount: a QEMU TCG plugin that counts the guest instructions executed inside
 * measured regions, exactly.
 *
 *   -plugin libspanlight_icount.so,begin=0xADDR,end=0xADDR,out=FILE[,profile=FILE]
 *
 * begin/end are the addresses of spanlight_measure_begin / spanlight_measure_end (the runner
 * looks them up with nm; a Thumb bit is ignored). Every executed instruction adds 1 to a
 * counter through an inline op QEMU compiles into the translated code; the first instruction
 * of each marker also gets a callback that snapshots the counter. A region is everything from
 * entering begin to entering end; the count is exact because it counts instructions as they
 * execute, not translation blocks (a block left early, or re-translated for device I/O under
 * -icount, would be over-counted), and repeatable because the guest is single-core and,
 * with -icount shift=0, even its timer readings are deterministic.
 *
 * At exit FILE (or QEMU's log, without out=) gets:
 *   spanlight-instructions: <sum over all regions>
 *   spanlight-regions: <number of completed regions>
 *   spanlight-region: <count>        one line per region, the first 1024
 *
 * With profile=FILE it also counts each instruction address inside the regions (code below
 * 4 MB, where the mps2 boards keep it) and writes "ADDRESS COUNT" lines, one per executed
 * instruction, for tools/qemu_icount/profile_on_qemu.sh to attribute to source lines.
 */
#include "qemu-plugin.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

QEMU_PLUGIN_EXPORT int qemu_plugin_version = QEMU_PLUGIN_VERSION;

enum { kRecordedRegions = 1024 };

static uint64_t begin_address;
static uint64_t end_address;
static const char *out_path;

static uint64_t executed; /* every guest instruction since start-up */
static int inside_region;
static uint64_t region_start;
static uint64_t total;
static uint64_t region_count;
static uint64_t region_sizes[kRecordedRegions];

/* Per-address counts (Thumb instructions are 2-byte aligned): running counts, their
 * snapshot at a region's begin, and the sum over regions. */
enum { kProfiledBytes = 4 << 20, kProfileSlots = kProfiledBytes / 2 };
static const char *profile_path;
static uint64_t *address_counts;
static uint64_t *address_snapshot;
static uint64_t *address_profile;

static void on_begin(unsigned int vcpu_index, void *userdata) {
  (void)vcpu_index;
  (void)userdata;
  if (!inside_region) { /* regions do not nest: a second begin is ignored */
    inside_region = 1;
    region_start = executed;
    if (address_counts != NULL) {
      memcpy(address_snapshot, address_counts, sizeof(uint64_t) * kProfileSlots);
    }
  }
}

static void on_end(unsigned int vcpu_index, void *userdata) {
  (void)vcpu_index;
  (void)userdata;
  if (inside_region) {
    const uint64_t size = executed - region_start;
    total += size;
    if (region_count < kRecordedRegions) {
      region_sizes[region_count] = size;
    }
    ++region_count;
    inside_region = 0;
    if (address_counts != NULL) {
      for (size_t i = 0; i < kProfileSlots; ++i) {
        address_profile[i] += address_counts[i] - address_snapshot[i];
      }
    }
  }
}

/* Runs once per translation, not per execution: instruments each instruction of the block. */
static void on_translate(qemu_plugin_id_t id, struct qemu_plugin_tb *tb) {
  (void)id;
  const size_t count = qemu_plugin_tb_n_insns(tb);
  for (size_t i = 0; i < count; ++i) {
    struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
    qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &executed, 1);
    const uint64_t address = qemu_plugin_insn_vaddr(insn);
    if (address_counts != NULL && address < kProfiledBytes) {
      qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &address_counts[address / 2], 1);
    }
    if (address == begin_address) {
      qemu_plugin_register_vcpu_insn_exec_cb(insn, on_begin, QEMU_PLUGIN_CB_NO_REGS, NULL);
    } else if (address == end_address) {
      qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, NULL);
    }
  }
}

static void write_report(FILE *out) {
  fprintf(out, "spanlight-instructions: %" PRIu64 "\n", total);
  fprintf(out, "spanlight-regions: %" PRIu64 "\n", region_count);
  for (uint64_t i = 0; i < region_count && i < kRecordedRegions; ++i) {
    fprintf(out, "spanlight-region: %" PRIu64 "\n", region_sizes[i]);
  }
  if (inside_region) {
    fprintf(out, "spanlight-unfinished-region: %" PRIu64 "\n", executed - region_start);
  }
}

static void write_profile(void) {
  FILE *out = fopen(profile_path, "w");
  if (out == NULL) {
    fprintf(stderr, "spanlight_icount: cannot write %s\n", profile_path);
    return;
  }
  for (size_t i = 0; i < kProfileSlots; ++i) {
    if (address_profile[i] != 0) {
      fprintf(out, "0x%zx %" PRIu64 "\n", i * 2, address_profile[i]);
    }
  }
  fclose(out);
}

static void on_exit_report(qemu_plugin_id_t id, void *userdata) {
  (void)id;
  (void)userdata;
  if (profile_path != NULL && address_profile != NULL) {
    write_profile();
  }
  if (out_path != NULL) {
    FILE *out = fopen(out_path, "w");
    if (out != NULL) {
      write_report(out);
      fclose(out);
      return;
    }
    fprintf(stderr, "spanlight_icount: cannot write %s\n", out_path);
  }
  char line[64];
  snprintf(line, sizeof line, "spanlight-instructions: %" PRIu64 "\n", total);
  qemu_plugin_outs(line);
}

/* Parses "name=value"; returns value when the argument has this name. */
static const char *argument_value(const char *argument, const char *name) {
  const size_t length = strlen(name);
  return strncmp(argument, name, length) == 0 && argument[length] == '=' ? argument + length + 1 : NULL;
}

static int parse_address(const char *text, uint64_t *address) {
  char *end = NULL;
  const unsigned long long value = strtoull(text, &end, 0);
  if (end == text || *end != '\0') {
    return 0;
  }
  *address = (uint64_t)value & ~(uint64_t)1; /* drop the Thumb bit of a function symbol */
  return 1;
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv) {
  (void)info;
  int have_begin = 0;
  int have_end = 0;
  for (int i = 0; i < argc; ++i) {
    const char *value = NULL;
    if ((value = argument_value(argv[i], "begin")) != NULL) {
      have_begin = parse_address(value, &begin_address);
    } else if ((value = argument_value(argv[i], "end")) != NULL) {
      have_end = parse_address(value, &end_address);
    } else if ((value = argument_value(argv[i], "out")) != NULL) {
      out_path = value; /* argv stays valid for the plugin's lifetime */
    } else if ((value = argument_value(argv[i], "profile")) != NULL) {
      profile_path = value;
    } else {
      fprintf(stderr, "spanlight_icount: unknown argument %s\n", argv[i]);
      return 1;
    }
  }
  if (!have_begin || !have_end) {
    fprintf(stderr, "spanlight_icount: needs begin=ADDRESS and end=ADDRESS\n");
    return 1;
  }
  if (profile_path != NULL) {
    address_counts = calloc(kProfileSlots, sizeof(uint64_t));
    address_snapshot = calloc(kProfileSlots, sizeof(uint64_t));
    address_profile = calloc(kProfileSlots, sizeof(uint64_t));
    if (address_counts == NULL || address_snapshot == NULL || address_profile == NULL) {
      fprintf(stderr, "spanlight_icount: out of memory for profile=\n");
      return 1;
    }
  }
  qemu_plugin_register_vcpu_tb_trans_cb(id, on_translate);
  qemu_plugin_register_atexit_cb(id, on_exit_report, NULL);
  return 0;
}
