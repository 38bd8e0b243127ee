#include "vtkStylizeAnimationEncoder.h"

#include "vtkObjectFactory.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

vtkStandardNewMacro(vtkStylizeAnimationEncoder);

//------------------------------------------------------------------------------
std::string vtkStylizeAnimationEncoder::Encode(const char* pattern, int fps, const char* output)
{
  const std::string out = output ? output : "";
  std::string ext = out.size() >= 4 ? out.substr(out.size() - 4) : std::string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (!pattern || !*pattern || (ext != ".gif" && ext != ".mp4"))
  {
    return "cannot encode \"" + out + "\": the animation must end in .gif or .mp4";
  }
  const std::string what = "cannot write \"" + out + "\"";
  const size_t slash = out.find_last_of('/');
  const std::string temporary =
    (slash == std::string::npos ? std::string() : out.substr(0, slash + 1)) + "." +
    out.substr(slash == std::string::npos ? 0 : slash + 1) + ".encoding" + ext;
  std::vector<std::string> args = { "ffmpeg", "-nostdin", "-y", "-v", "error", "-framerate",
    std::to_string(std::min(120, std::max(1, fps))), "-i", pattern };
  if (ext == ".gif")
  {
    // one palette from all the frames' colours (comic: black, white and gray; pixel art: its
    // palette), no dithering of its own
    args.insert(args.end(),
      { "-vf", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=none", "-loop",
        "0" });
  }
  else
  {
    args.insert(args.end(),
      { "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
        "18" });
  }
  args.push_back(temporary);
  std::vector<char*> argv;
  for (std::string& a : args)
  {
    argv.push_back(&a[0]);
  }
  argv.push_back(nullptr);
  pid_t pid = -1;
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  const int spawned = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
  {
    return what + ": ffmpeg could not be run (" + std::strerror(spawned) +
      "; Debian: apt-get install ffmpeg); the frames are written";
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    ::unlink(temporary.c_str());
    return what + ": ffmpeg failed (exit status " +
      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "); the frames are written";
  }
  if (std::rename(temporary.c_str(), out.c_str()) != 0)
  {
    const int error = errno;
    ::unlink(temporary.c_str());
    return what + ": " + std::strerror(error);
  }
  return std::string();
}
