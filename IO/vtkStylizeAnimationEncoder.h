/**
 * @class   vtkStylizeAnimationEncoder
 * @brief   Encodes numbered PNG frames into a GIF or MP4 animation with ffmpeg.
 *
 * The orbit animations of vtkstylize (--orbit), of the Python package (vtkstylize.encode) and
 * of ParaView's stylized view (SaveStylizedOrbit) are PNG frames encoded by ffmpeg (Debian:
 * apt-get install ffmpeg), which runs as a child process. The file is encoded under a hidden
 * name beside it and renamed when ffmpeg succeeds: a failure leaves no partial file.
 */

#ifndef vtkStylizeAnimationEncoder_h
#define vtkStylizeAnimationEncoder_h

#include "vtkObject.h"
#include "vtkStylizeIOModule.h" // for export macro

#include <string> // for std::string

class VTKSTYLIZEIO_EXPORT vtkStylizeAnimationEncoder : public vtkObject
{
public:
  static vtkStylizeAnimationEncoder* New();
  vtkTypeMacro(vtkStylizeAnimationEncoder, vtkObject);

  /**
   * Encodes the frames `pattern` names (ffmpeg's printf-style name, e.g. frame-%04d.png) at `fps`
   * frames per second (clamped to [1, 120]) into `output`, which ends in .gif (one palette from
   * all the frames' colours, no dithering of ffmpeg's own, looping) or .mp4 (H.264, yuv420p,
   * CRF 18, sides padded to even). Returns "" on success, the failure's line otherwise; the
   * frames are left as they are.
   */
  static std::string Encode(const char* pattern, int fps, const char* output);

protected:
  vtkStylizeAnimationEncoder() = default;
  ~vtkStylizeAnimationEncoder() override = default;

private:
  vtkStylizeAnimationEncoder(const vtkStylizeAnimationEncoder&) = delete;
  void operator=(const vtkStylizeAnimationEncoder&) = delete;
};

#endif
