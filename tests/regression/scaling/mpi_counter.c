/* Counts this rank's MPI traffic through the standard profiling interface (PMPI), for the weak-scaling test:
 * point-to-point messages and bytes sent, collective calls and the bytes this rank contributes to them.
 * Counting runs while MPI_Pcontrol's level is > 0 (parcelflow raises it for its coupled loop and lowers it
 * after); at MPI_Finalize every rank appends one line to $MPI_COUNTER_FILE:
 *   rank messages bytes_sent collectives collective_bytes max_rss_kb partners
 * Preloaded (LD_PRELOAD) into parcelflow by weak_scaling.py; not linked into anything else. */
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>

static int counting = 0;
static long long messages = 0, bytes = 0, collectives = 0, collective_bytes = 0;
static unsigned long long partners = 0; /* bit r: this rank sent to world rank r (r < 64) */

static long long size_of(int count, MPI_Datatype type) {
  int s = 0;
  PMPI_Type_size(type, &s);
  return (long long)count * s;
}

static void p2p(int count, MPI_Datatype type, int dest, MPI_Comm comm) {
  if (!counting) return;
  ++messages;
  bytes += size_of(count, type);
  MPI_Group group, world;
  int world_rank = MPI_UNDEFINED;
  PMPI_Comm_group(comm, &group);
  PMPI_Comm_group(MPI_COMM_WORLD, &world);
  PMPI_Group_translate_ranks(group, 1, &dest, world, &world_rank);
  PMPI_Group_free(&group);
  PMPI_Group_free(&world);
  if (world_rank >= 0 && world_rank < 64) partners |= 1ull << world_rank;
}

static void collective(long long sent) {
  if (!counting) return;
  ++collectives;
  collective_bytes += sent;
}

static int ranks(MPI_Comm comm) {
  int n = 1;
  PMPI_Comm_size(comm, &n);
  return n;
}

int MPI_Pcontrol(const int level, ...) {
  counting = level > 0;
  return MPI_SUCCESS;
}

int MPI_Send(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm) {
  p2p(c, t, d, comm);
  return PMPI_Send(b, c, t, d, tag, comm);
}
int MPI_Rsend(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm) {
  p2p(c, t, d, comm);
  return PMPI_Rsend(b, c, t, d, tag, comm);
}
int MPI_Ssend(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm) {
  p2p(c, t, d, comm);
  return PMPI_Ssend(b, c, t, d, tag, comm);
}
int MPI_Isend(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm, MPI_Request* r) {
  p2p(c, t, d, comm);
  return PMPI_Isend(b, c, t, d, tag, comm, r);
}
int MPI_Irsend(const void* b, int c, MPI_Datatype t, int d, int tag, MPI_Comm comm, MPI_Request* r) {
  p2p(c, t, d, comm);
  return PMPI_Irsend(b, c, t, d, tag, comm, r);
}
int MPI_Sendrecv(const void* sb, int sc, MPI_Datatype st, int d, int stag, void* rb, int rc, MPI_Datatype rt, int s,
                 int rtag, MPI_Comm comm, MPI_Status* status) {
  p2p(sc, st, d, comm);
  return PMPI_Sendrecv(sb, sc, st, d, stag, rb, rc, rt, s, rtag, comm, status);
}
int MPI_Allreduce(const void* sb, void* rb, int c, MPI_Datatype t, MPI_Op op, MPI_Comm comm) {
  collective(size_of(c, t));
  return PMPI_Allreduce(sb, rb, c, t, op, comm);
}
int MPI_Reduce(const void* sb, void* rb, int c, MPI_Datatype t, MPI_Op op, int root, MPI_Comm comm) {
  collective(size_of(c, t));
  return PMPI_Reduce(sb, rb, c, t, op, root, comm);
}
int MPI_Bcast(void* b, int c, MPI_Datatype t, int root, MPI_Comm comm) {
  collective(size_of(c, t));
  return PMPI_Bcast(b, c, t, root, comm);
}
int MPI_Barrier(MPI_Comm comm) {
  collective(0);
  return PMPI_Barrier(comm);
}
int MPI_Scan(const void* sb, void* rb, int c, MPI_Datatype t, MPI_Op op, MPI_Comm comm) {
  collective(size_of(c, t));
  return PMPI_Scan(sb, rb, c, t, op, comm);
}
int MPI_Exscan(const void* sb, void* rb, int c, MPI_Datatype t, MPI_Op op, MPI_Comm comm) {
  collective(size_of(c, t));
  return PMPI_Exscan(sb, rb, c, t, op, comm);
}
int MPI_Alltoall(const void* sb, int sc, MPI_Datatype st, void* rb, int rc, MPI_Datatype rt, MPI_Comm comm) {
  collective(size_of(sc, st) * ranks(comm));
  return PMPI_Alltoall(sb, sc, st, rb, rc, rt, comm);
}
int MPI_Alltoallv(const void* sb, const int* sc, const int* sd, MPI_Datatype st, void* rb, const int* rc,
                  const int* rd, MPI_Datatype rt, MPI_Comm comm) {
  long long sent = 0;
  for (int r = 0, n = ranks(comm); r < n; ++r) sent += size_of(sc[r], st);
  collective(sent);
  return PMPI_Alltoallv(sb, sc, sd, st, rb, rc, rd, rt, comm);
}
int MPI_Allgather(const void* sb, int sc, MPI_Datatype st, void* rb, int rc, MPI_Datatype rt, MPI_Comm comm) {
  collective(size_of(sc, st));
  return PMPI_Allgather(sb, sc, st, rb, rc, rt, comm);
}
int MPI_Allgatherv(const void* sb, int sc, MPI_Datatype st, void* rb, const int* rc, const int* rd, MPI_Datatype rt,
                   MPI_Comm comm) {
  collective(size_of(sc, st));
  return PMPI_Allgatherv(sb, sc, st, rb, rc, rd, rt, comm);
}
int MPI_Gather(const void* sb, int sc, MPI_Datatype st, void* rb, int rc, MPI_Datatype rt, int root, MPI_Comm comm) {
  collective(size_of(sc, st));
  return PMPI_Gather(sb, sc, st, rb, rc, rt, root, comm);
}
int MPI_Gatherv(const void* sb, int sc, MPI_Datatype st, void* rb, const int* rc, const int* rd, MPI_Datatype rt,
                int root, MPI_Comm comm) {
  collective(size_of(sc, st));
  return PMPI_Gatherv(sb, sc, st, rb, rc, rd, rt, root, comm);
}

int MPI_Finalize(void) {
  int rank = 0;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank);
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const char* path = getenv("MPI_COUNTER_FILE");
  if (path) {
    FILE* f = fopen(path, "a");
    if (f) {
      fprintf(f, "%d %lld %lld %lld %lld %ld %d\n", rank, messages, bytes, collectives, collective_bytes,
              usage.ru_maxrss, __builtin_popcountll(partners));
      fclose(f);
    }
  }
  return PMPI_Finalize();
}
