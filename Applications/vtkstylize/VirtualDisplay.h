// vtkstylize: a virtual X server for a run without a display (a server, a batch job, CI).
#ifndef vtkstylize_VirtualDisplay_h
#define vtkstylize_VirtualDisplay_h

namespace vtkstylize
{
/**
 * When DISPLAY is not set, starts Xvfb on a free display (-displayfd: the server picks the
 * number), at least width x height pixels, and sets DISPLAY to it for this process. Fails with
 * one line when Xvfb is not installed (naming the package) or does not start. Does nothing when
 * DISPLAY is set or a virtual display runs already.
 */
void StartVirtualDisplayIfNeeded(int width, int height);

/**
 * Stops the virtual display, if one was started (async-signal-safe: the crash and interrupt
 * handlers call it). The server also ends when this process dies (PR_SET_PDEATHSIG).
 */
void StopVirtualDisplay();
}

#endif
