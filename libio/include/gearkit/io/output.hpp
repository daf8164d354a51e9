#pragma once
// Every file a command writes goes through an OutputSet: outputs are rendered and checked first,
// then committed together, so that a bad destination, a full disk or a kill never leaves a
// half-written file and never destroys an input. docs/cli.md ("Output files") states the
// guarantees for users.
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gearkit::io {

/// Remembers that this process reads `path` (by device and inode), so that no output may
/// replace it. load_yaml_file() calls it for every model file; call it for any other file a
/// command reads. A path that cannot be stat'ed is ignored (reading it fails elsewhere).
void note_input_file(const std::string& path);

/// Forgets the files noted so far (for tests that run several commands in one process).
void forget_input_files();

/// The paths noted by note_input_file() so far, in the order they were read (an HTML report lists
/// them with their content as the run's inputs).
std::vector<std::string> input_files();

/// The suffix of the temporary files an OutputSet creates next to each destination:
/// ".<name>.<pid>-<6 letters>.gearkit-tmp". A later OutputSet writing into the same folder
/// removes those whose process no longer runs (left by a kill).
inline constexpr std::string_view kTemporarySuffix = ".gearkit-tmp";

/// Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE that remove every temporary an
/// OutputSet has open, then end the process by the same signal (its default action: the exit
/// status still says which signal). A signal ignored when this is called stays ignored. Call it
/// once, at the start of main(); without it a signal leaves the temporaries for the next run.
/// SIGKILL cannot be caught: what it leaves is described in docs/cli.md ("Output files").
void remove_temporaries_on_signals();

/// A set of pending outputs, committed all together or not at all.
///
/// Destinations: a path (written through symlinks to their target, keeping the target's
/// permissions, owner and hard links), "-" for standard output, a character device or a FIFO
/// (written directly). An empty path, a folder, a missing folder, a read-only file, a block
/// device or socket, a file that is also an input (same device and inode, through links) and
/// a destination named twice are refused when the output is added, before anything is written.
/// So is "-" when the shell opened standard output on an input file (`1<>model.yaml`, `>>`).
///
/// Regular files are first written in full to a temporary file in the destination's folder;
/// commit() writes the standard-output and device outputs, then renames each temporary over
/// its destination (or copies it into place for a file with several hard links, or whose
/// owner a rename would change). Destroying the set without commit() removes the temporaries
/// and leaves every destination as it was.
///
/// Every failure throws InputError "option '--dxf': cannot write 'c.dxf': reason" (exit 2).
class OutputSet {
 public:
  /// @param standard_output where "-" goes (the command's output stream).
  explicit OutputSet(std::ostream& standard_output);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Adds an output whose content is complete.
  /// @param option the option that named the destination, as typed ("--svg"), for messages.
  /// @param path the destination as the user gave it.
  /// @throws InputError as described above; nothing is written to the destination.
  void add(std::string_view option, const std::string& path, std::string_view content);

  /// Adds an output written incrementally (a sweep report row by row). The stream writes to
  /// the temporary file (or straight to standard output or the device) and stays valid until
  /// the set is destroyed; commit() puts it in place. Write errors surface in commit().
  /// @throws InputError as add().
  std::ostream& stream(std::string_view option, const std::string& path);

  /// Claims a destination whose content is not known yet (a plot of a sweep still running): it
  /// is checked and refused now, as add() does, so that nothing is streamed before a bad
  /// destination is found. fill() gives the content; an output never filled is dropped at
  /// commit() and its destination stays as it was.
  /// @throws InputError as add().
  void reserve(std::string_view option, const std::string& path);
  /// The content of the output reserved for `option`. @throws std::logic_error if none is.
  void fill(std::string_view option, std::string_view content);
  /// The option of the output that goes to standard output ("-"), if one does.
  std::optional<std::string> standard_output_option() const;

  /// Puts every output in place; afterwards the set is empty.
  /// @throws InputError when a write fails (disk full, device error); regular-file outputs are
  ///         then all left as they were unless the failure happens in the final renames.
  void commit();

  /// An SVG picture among the pending outputs (an HTML report shows it inline).
  struct Picture {
    std::string option;  ///< "--svg", "--plot"...
    std::string path;    ///< as the user gave it
    std::string svg;     ///< the document
  };
  /// The outputs added whose content is an SVG document, in the order they were added.
  std::vector<Picture> pictures() const;

  struct Output;  // one pending output (defined in output.cpp)

 private:
  Output& add_output(std::string_view option, const std::string& path);
  void finish_temporaries();
  void write_direct_outputs();
  void move_into_place();

  std::ostream& standard_output_;
  std::vector<std::unique_ptr<Output>> outputs_;
};

}  // namespace gearkit::io
