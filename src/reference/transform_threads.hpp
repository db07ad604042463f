#pragma once
/// @file
/// The threads one large transform is split over. The cosine transform's lines go in
/// blocks of eight, each block's even extensions, FFT and cosine sums computed alone (by one
/// thread, whichever), so a transform gives the same bits on any number of threads: a curve
/// built on four threads is the curve built on one, and a cache or a map that reads it does
/// not know how it was built. Transforms of fewer than kThreadedValues values stay on one
/// thread (a parallel region's start costs more than they take).

namespace punchsweep::reference {

/// Transforms of at least this many values are split over the threads (a 128 x 128 quarter).
inline constexpr long kThreadedValues = 128L * 128L;

/// The threads a large transform is split over: set_transform_threads's, else
/// default_transform_threads().
int transform_threads();

/// The threads a transform of `values` values is split over: transform_threads() from
/// kThreadedValues, else one.
inline int threads_for(long values) { return values >= kThreadedValues ? transform_threads() : 1; }

/// Sets them (at least 1; a value beyond the CPUs only oversubscribes them). For the whole
/// process; not to be changed while a transform runs.
void set_transform_threads(int threads);

/// Makes a process forked from this one run its transforms on one thread (GNU OpenMP's
/// threads do not survive a fork: Python's multiprocessing forks). Called before the first
/// transform (prepare_fftw); once a process.
void one_thread_after_fork();

/// The threads a process takes unless told (threads_given with this process's CPUs).
int default_transform_threads();

/// OMP_NUM_THREADS where it is set to a positive whole number; else the CPUs of the
/// affinity mask where a launcher narrowed it below the machine's (`affinity` < `machine`:
/// mpirun's or srun's binding, Slurm's --cpus-per-task, taskset: those cores are this
/// process's); else one. Not every core by default: GNU OpenMP's threads spin while they
/// wait, so two processes that each took both cores of this machine took 195 s for what
/// each does in 4 s alone (measured); a process that shares its cores must not take them all.
int threads_given(int affinity, int machine);

/// The CPUs of this process's affinity mask (at least 1), and of the machine.
int affinity_cpus();
int machine_cpus();

}  // namespace punchsweep::reference
