//! The language's own words with what each does, in a sentence or two of
//! our own from the Siemens manuals, and the manual it rests on: one table
//! that the editor's hover and completion and the documentation share.
//!
//! G and M functions are in [`crate::semantic::functions`] (numbered, with
//! their groups), except G290 and G291, which switch the language itself;
//! the cycles and their parameters in [`crate::semantic::cycles`]. A word
//! whose meaning no manual at hand confirms is left out rather than
//! guessed: `PUNCH_ON` and `PUNCH_OFF`, which TRUMPF machines define, are
//! two.

use crate::semantic::functions;
use Kind::{Command, Function, Keyword, Procedure, SystemVariable};

/// What kind of word it is, as an editor groups them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// A control-flow or declaration word (`IF`, `DEF`, `GOTOF`, `AND`).
    Keyword,
    /// A command on a block of its own or among addresses (`STOPRE`,
    /// `SUPA`, `TRAORI`, `G17` is not one: it is a G function).
    Command,
    /// A function that gives a value (`SIN`, `TRUNC`, `CTRANS`).
    Function,
    /// A predefined procedure called by name (`SETMS`, `WAITM`).
    Procedure,
    /// A `$` system variable of the control (`$P_UIFR`, `$AA_IM`).
    SystemVariable,
}

/// One word of the language.
#[derive(Clone, Copy, Debug)]
pub struct Word {
    /// As the manuals spell it.
    pub name: &'static str,
    pub kind: Kind,
    /// What it does, in one or two sentences.
    pub meaning: &'static str,
    /// The manual the meaning rests on.
    pub manual: &'static str,
}

/// The Programming Manual Fundamentals.
const FUNDAMENTALS: &str = "Programming Manual Fundamentals";
/// The Programming Manual Job Planning.
const JOB_PLANNING: &str = "Programming Manual Job Planning";
/// The Function Manual Synchronized Actions.
const SYNCHRONIZED_ACTIONS: &str = "Function Manual Synchronized Actions";
/// The List Manual System Variables.
const SYSTEM_VARIABLES: &str = "List Manual System Variables";

/// Where the dynamic response groups (technology G group 59) are described.
const BASIC_FUNCTIONS: &str = "Function Manual Basic Functions (B2, Acceleration)";

/// One row of [`WORDS`], on one line each.
const fn entry(
    name: &'static str,
    kind: Kind,
    meaning: &'static str,
    manual: &'static str,
) -> Word {
    Word {
        name,
        kind,
        meaning,
        manual,
    }
}

/// Every word described, grouped as the manuals group them.
pub const WORDS: &[Word] = &[
    // Program flow (Job Planning, "Flexible NC programming").
    entry("IF", Keyword, "Starts a branch that runs only if its condition is true, up to ELSE or ENDIF; followed by a jump in the same block, it jumps only when the condition holds.", JOB_PLANNING),
    entry("ELSE", Keyword, "Starts the part of an IF branch that runs when the condition is false.", JOB_PLANNING),
    entry("ENDIF", Keyword, "Ends an IF branch.", JOB_PLANNING),
    entry("WHILE", Keyword, "Starts a loop that repeats, up to ENDWHILE, as long as its condition is true; the condition is checked before each pass.", JOB_PLANNING),
    entry("ENDWHILE", Keyword, "Ends a WHILE loop.", JOB_PLANNING),
    entry("FOR", Keyword, "Starts a counting loop: the variable runs from the start value to the end value (TO) in steps of one, the blocks up to ENDFOR running once per value.", JOB_PLANNING),
    entry("TO", Keyword, "Separates a FOR loop's start value from its end value; after CALL BLOCK, names the last label of the section called.", JOB_PLANNING),
    entry("ENDFOR", Keyword, "Ends a FOR loop.", JOB_PLANNING),
    entry("LOOP", Keyword, "Starts an endless loop, up to ENDLOOP, left only by a jump or the end of the program.", JOB_PLANNING),
    entry("ENDLOOP", Keyword, "Ends a LOOP.", JOB_PLANNING),
    entry("REPEAT", Keyword, "Alone, starts a loop that repeats up to UNTIL until its condition is true; with labels, runs that section of the program again (P= times).", JOB_PLANNING),
    entry("REPEATB", Keyword, "Runs the single block at the label named again (P= times).", JOB_PLANNING),
    entry("UNTIL", Keyword, "Ends a REPEAT loop: the loop is left once its condition is true, checked after each pass.", JOB_PLANNING),
    entry("CASE", Keyword, "Jumps according to the value of an expression: to the label after the first constant (OF) that equals it, otherwise to the one after DEFAULT.", JOB_PLANNING),
    entry("OF", Keyword, "Introduces the constants and jumps of a CASE block.", JOB_PLANNING),
    entry("DEFAULT", Keyword, "In a CASE block, the jump taken when no constant equals the value.", JOB_PLANNING),
    entry("GOTO", Keyword, "Jumps to the label or block number named, searching first towards the end of the program and then from its start.", JOB_PLANNING),
    entry("GOTOF", Keyword, "Jumps forward, towards the end of the program, to the label or block number named.", JOB_PLANNING),
    entry("GOTOB", Keyword, "Jumps backward, towards the start of the program, to the label or block number named.", JOB_PLANNING),
    entry("GOTOC", Keyword, "Jumps as GOTO does, but a target not found raises no alarm: the program goes on with the next block.", JOB_PLANNING),
    entry("GOTOS", Keyword, "Jumps back to the start of the program.", JOB_PLANNING),
    entry("AND", Keyword, "Logical AND; note that it binds more strongly than a comparison, so comparisons joined by it are written in parentheses.", JOB_PLANNING),
    entry("OR", Keyword, "Logical OR; it binds more strongly than a comparison.", JOB_PLANNING),
    entry("XOR", Keyword, "Logical exclusive OR: true when exactly one side is true.", JOB_PLANNING),
    entry("NOT", Keyword, "Logical negation.", JOB_PLANNING),
    entry("B_AND", Keyword, "Bit-by-bit AND of two integers.", JOB_PLANNING),
    entry("B_OR", Keyword, "Bit-by-bit OR of two integers.", JOB_PLANNING),
    entry("B_XOR", Keyword, "Bit-by-bit exclusive OR of two integers.", JOB_PLANNING),
    entry("B_NOT", Keyword, "Bit-by-bit negation of an integer.", JOB_PLANNING),
    entry("DIV", Keyword, "Integer division: the quotient without its fractional part.", JOB_PLANNING),
    entry("MOD", Keyword, "The remainder of an integer division.", JOB_PLANNING),
    entry("TRUE", Keyword, "The logical constant true (1).", JOB_PLANNING),
    entry("FALSE", Keyword, "The logical constant false (0).", JOB_PLANNING),
    // Variables and macros (Job Planning, "Flexible NC programming").
    entry("DEF", Keyword, "Defines a variable with its type (and for global user data its range, NCK or CHAN); the definitions stand before the first executable block.", JOB_PLANNING),
    entry("REDEF", Keyword, "Changes the attributes of a variable already defined (its access rights, its initial value's moment, its synchronisation).", JOB_PLANNING),
    entry("DEFINE", Keyword, "Defines a macro: DEFINE name AS text, the name then standing for the text.", JOB_PLANNING),
    entry("AS", Keyword, "Separates a macro's name from the text it stands for, in DEFINE.", JOB_PLANNING),
    entry("INT", Keyword, "Data type: a signed integer.", JOB_PLANNING),
    entry("REAL", Keyword, "Data type: a signed floating-point number.", JOB_PLANNING),
    entry("BOOL", Keyword, "Data type: a truth value, TRUE or FALSE (1 or 0).", JOB_PLANNING),
    entry("CHAR", Keyword, "Data type: one ASCII character, a code from 0 to 255.", JOB_PLANNING),
    entry("STRING", Keyword, "Data type: a character string of the length given in brackets, at most 200 characters.", JOB_PLANNING),
    entry("AXIS", Keyword, "Data type: an axis name (a geometry, channel or machine axis identifier).", JOB_PLANNING),
    entry("FRAME", Keyword, "Data type: a coordinate transformation made of translation, rotation, scaling and mirroring per axis.", JOB_PLANNING),
    entry("SET", Function, "Initialises an array with the list of values given, element by element.", JOB_PLANNING),
    entry("REP", Function, "Initialises every remaining element of an array with the one value given.", JOB_PLANNING),
    // Subprograms (Fundamentals and Job Planning, "Subprogram technique").
    entry("PROC", Keyword, "Begins a subprogram's definition: its name, its parameters in parentheses (VAR for one passed by reference) and its attributes.", JOB_PLANNING),
    entry("EXTERN", Keyword, "Declares a subprogram with parameters that is defined in another file, so that a call of it can be checked and its arguments passed.", JOB_PLANNING),
    entry("RET", Procedure, "Ends a subprogram and returns to the calling program, as M17 does but without an auxiliary function output.", FUNDAMENTALS),
    entry("CALL", Keyword, "Calls a subprogram whose name is given as a string or a variable (an indirect call); with BLOCK ... TO, runs only a section of it.", JOB_PLANNING),
    entry("PCALL", Keyword, "Calls a subprogram by its absolute path, with parameters.", JOB_PLANNING),
    entry("MCALL", Keyword, "Calls the subprogram named after every following block that moves an axis (a modal call), until MCALL alone ends it.", FUNDAMENTALS),
    entry("EXTCALL", Keyword, "Calls a subprogram from outside the control's program memory (a drive or the HMI) and runs it as it is read in.", JOB_PLANNING),
    entry("ISOCALL", Keyword, "Calls a program written in an ISO dialect (G code of another control) by name.", JOB_PLANNING),
    entry("SAVE", Command, "Subprogram attribute: the modal G functions and the programmable frame in force at the call are restored when the subprogram returns.", JOB_PLANNING),
    entry("SBLOF", Procedure, "Suppresses single block mode for the blocks that follow (or, as a PROC attribute, for the whole subprogram), so they run as one step.", JOB_PLANNING),
    entry("SBLON", Procedure, "Ends the suppression of single block mode that SBLOF started.", JOB_PLANNING),
    entry("DISPLOF", Command, "Subprogram attribute: the blocks of the subprogram are not shown as the current block; the call is shown instead.", JOB_PLANNING),
    entry("DISPLON", Command, "Ends the suppression of the current block display that DISPLOF asked for.", JOB_PLANNING),
    // Synchronized actions (Function Manual Synchronized Actions).
    entry("ID", Command, "Numbers a modal synchronized action, local to the program: it stays active until the program ends or it is cancelled (CANCEL).", SYNCHRONIZED_ACTIONS),
    entry("IDS", Command, "Numbers a static synchronized action: it stays active across programs, in every mode, until it is cancelled.", SYNCHRONIZED_ACTIONS),
    entry("WHEN", Keyword, "Synchronized action condition: the action runs once, the first time the condition is true.", SYNCHRONIZED_ACTIONS),
    entry("WHENEVER", Keyword, "Synchronized action condition: the action runs in every interpolation cycle in which the condition is true.", SYNCHRONIZED_ACTIONS),
    entry("FROM", Keyword, "Synchronized action condition: once the condition has been true, the action runs in every cycle from then on, while the synchronized action is active.", SYNCHRONIZED_ACTIONS),
    entry("EVERY", Keyword, "Synchronized action condition: the action runs each time the condition changes from false to true.", SYNCHRONIZED_ACTIONS),
    entry("DO", Keyword, "Introduces the actions of a synchronized action, run when its condition is met.", SYNCHRONIZED_ACTIONS),
    entry("CANCEL", Procedure, "Cancels the modal or static synchronized action with the ID number given.", SYNCHRONIZED_ACTIONS),
    entry("OVR", Command, "A programmed override of the path feed, in percent (OVRA for one axis or spindle).", FUNDAMENTALS),
    // Frames (Fundamentals, "Coordinate transformations (frames)").
    entry("TRANS", Keyword, "Programmable zero offset along the axes named, replacing the programmable frame (offset, rotation, scale, mirror); TRANS alone clears it.", FUNDAMENTALS),
    entry("ATRANS", Keyword, "Programmable zero offset along the axes named, added to the programmable frame already in force.", FUNDAMENTALS),
    entry("ROT", Keyword, "Programmable rotation about the axes named (or by RPL in the working plane), replacing the programmable frame; ROT alone clears it.", FUNDAMENTALS),
    entry("AROT", Keyword, "Programmable rotation about the axes named (or by RPL in the plane), added to the programmable frame: it turns about the axes already rotated.", FUNDAMENTALS),
    entry("ROTS", Keyword, "Programmable rotation given by solid angles (the traces of the inclined plane), replacing the programmable frame.", FUNDAMENTALS),
    entry("AROTS", Keyword, "Programmable rotation given by solid angles, added to the programmable frame.", FUNDAMENTALS),
    entry("CROTS", Keyword, "Rotation given by solid angles, relative to the frame valid in the data management; also a function that returns such a frame.", FUNDAMENTALS),
    entry("SCALE", Keyword, "Programmable scale factor per axis, replacing the programmable frame; SCALE alone clears it.", FUNDAMENTALS),
    entry("ASCALE", Keyword, "Programmable scale factor per axis, added to the programmable frame.", FUNDAMENTALS),
    entry("MIRROR", Keyword, "Programmable mirroring of the axes named, replacing the programmable frame; MIRROR alone clears it.", FUNDAMENTALS),
    entry("AMIRROR", Keyword, "Programmable mirroring of the axes named, added to the programmable frame.", FUNDAMENTALS),
    entry("RPL", Command, "The angle of a rotation in the working plane, with ROT or AROT (about the axis normal to the plane G17, G18 or G19 selects).", FUNDAMENTALS),
    entry("CTRANS", Function, "Returns a frame that offsets the axes named by the values given, nothing else.", JOB_PLANNING),
    entry("CROT", Function, "Returns a frame that rotates about the axes named by the angles given.", JOB_PLANNING),
    entry("CSCALE", Function, "Returns a frame that scales the axes named by the factors given.", JOB_PLANNING),
    entry("CMIRROR", Function, "Returns a frame that mirrors the axes named.", JOB_PLANNING),
    entry("CFINE", Function, "Returns a frame whose fine offsets along the axes named are the values given.", JOB_PLANNING),
    // Dimensions (Fundamentals, "Dimensions").
    entry("AC", Function, "Absolute dimension for this axis value only, whatever G90 or G91 is in force: X=AC(10).", FUNDAMENTALS),
    entry("IC", Function, "Incremental dimension for this axis value only, whatever G90 or G91 is in force: X=IC(10).", FUNDAMENTALS),
    entry("DC", Function, "A rotary axis goes to the absolute position given by the shortest way.", FUNDAMENTALS),
    entry("ACP", Function, "A rotary axis goes to the absolute position given turning in the positive direction.", FUNDAMENTALS),
    entry("ACN", Function, "A rotary axis goes to the absolute position given turning in the negative direction.", FUNDAMENTALS),
    entry("CAC", Function, "An indexing axis goes to the position the indexing table holds at the index given, absolutely.", JOB_PLANNING),
    entry("CIC", Function, "An indexing axis moves on by the number of indexing positions given, incrementally.", JOB_PLANNING),
    entry("CACP", Function, "An indexing axis goes to the indexed position given turning in the positive direction.", JOB_PLANNING),
    entry("CACN", Function, "An indexing axis goes to the indexed position given turning in the negative direction.", JOB_PLANNING),
    entry("DIAMON", Command, "Diameter programming on: the transverse axis's positions are read as diameters.", FUNDAMENTALS),
    entry("DIAMOF", Command, "Diameter programming off: the transverse axis's positions are read as radii.", FUNDAMENTALS),
    // Arithmetic (Job Planning, "Arithmetic functions"); angles are in degrees.
    entry("SIN", Function, "The sine of an angle in degrees.", JOB_PLANNING),
    entry("COS", Function, "The cosine of an angle in degrees.", JOB_PLANNING),
    entry("TAN", Function, "The tangent of an angle in degrees.", JOB_PLANNING),
    entry("ASIN", Function, "The arc sine, in degrees.", JOB_PLANNING),
    entry("ACOS", Function, "The arc cosine, in degrees.", JOB_PLANNING),
    entry("ATAN2", Function, "The angle in degrees of the vector whose two components are given (ordinate first), in the whole circle.", JOB_PLANNING),
    entry("SQRT", Function, "The square root.", JOB_PLANNING),
    entry("ABS", Function, "The absolute value.", JOB_PLANNING),
    entry("POT", Function, "The square of a value.", JOB_PLANNING),
    entry("TRUNC", Function, "The integer part of a value, the decimals cut off.", JOB_PLANNING),
    entry("ROUND", Function, "A value rounded to the nearest integer.", JOB_PLANNING),
    entry("LN", Function, "The natural logarithm.", JOB_PLANNING),
    entry("EXP", Function, "The exponential function, e to the power of the value.", JOB_PLANNING),
    entry("MINVAL", Function, "The smaller of two values.", JOB_PLANNING),
    entry("MAXVAL", Function, "The larger of two values.", JOB_PLANNING),
    entry("BOUND", Function, "A value limited to the range given: the value itself inside it, the nearer limit outside it.", JOB_PLANNING),
    // Strings and checks (Job Planning, "String operations", "Check scope of NC language").
    entry("SPRINT", Function, "Returns a string formatted from the format string and values given (%D, %F, %S and others as placeholders).", JOB_PLANNING),
    entry("SUBSTR", Function, "Returns the part of a string from the position given, of the length given.", JOB_PLANNING),
    entry("TOLOWER", Function, "Returns a string with its letters in lower case.", JOB_PLANNING),
    entry("TOUPPER", Function, "Returns a string with its letters in upper case.", JOB_PLANNING),
    entry("STRLEN", Function, "The number of characters of a string.", JOB_PLANNING),
    entry("INDEX", Function, "The position of the first occurrence of a character in a string, or -1.", JOB_PLANNING),
    entry("RINDEX", Function, "The position of the last occurrence of a character in a string, or -1.", JOB_PLANNING),
    entry("MATCH", Function, "The position of the first occurrence of a string in another, or -1.", JOB_PLANNING),
    entry("NUMBER", Function, "Converts a string into a number.", JOB_PLANNING),
    entry("ISNUMBER", Function, "Whether a string can be converted into a number.", JOB_PLANNING),
    entry("AXNAME", Function, "Converts a string into an axis name.", JOB_PLANNING),
    entry("AXSTRING", Function, "Converts an axis name (or a spindle number) into a string.", JOB_PLANNING),
    entry("ISAXIS", Function, "Whether the geometry axis given by its number (1 to 3) exists.", JOB_PLANNING),
    entry("ISVAR", Function, "Whether the name given is a variable the control knows (a system variable, machine or setting data, or a user variable).", JOB_PLANNING),
    entry("ISFILE", Function, "Whether the file named exists in the control's program memory.", JOB_PLANNING),
    entry("MSG", Procedure, "Shows the text given as a message on the operator screen; MSG() clears it.", FUNDAMENTALS),
    entry("SETAL", Procedure, "Raises the cycle alarm with the number given, optionally with a text.", JOB_PLANNING),
    entry("EXECSTRING", Procedure, "Runs the string given as a block of the program.", JOB_PLANNING),
    entry("WRITE", Procedure, "Appends a block of text to the end of the file named, returning an error code in its first parameter.", JOB_PLANNING),
    // Preprocessing, interrupts, channels (Job Planning).
    entry("STOPRE", Procedure, "Stops the block preprocessing until every block before it has been executed, so that a value read next (a measured position, a system variable) is the current one.", JOB_PLANNING),
    entry("SETINT", Procedure, "Assigns an interrupt routine to a fast NC input: when the input switches, the program is interrupted and the routine runs.", JOB_PLANNING),
    entry("PRIO", Command, "The priority of an interrupt routine assigned by SETINT (1 highest, 128 lowest).", JOB_PLANNING),
    entry("BLSYNC", Command, "With SETINT: the interrupt routine starts only at the next block change.", JOB_PLANNING),
    entry("LIFTFAST", Command, "With SETINT: the tool retracts quickly from the contour before the interrupt routine starts.", JOB_PLANNING),
    entry("ENABLE", Procedure, "Enables the interrupt routine of the input given again.", JOB_PLANNING),
    entry("DISABLE", Procedure, "Disables the interrupt routine of the input given, keeping its assignment.", JOB_PLANNING),
    entry("CLRINT", Procedure, "Removes the assignment of an interrupt routine to the input given.", JOB_PLANNING),
    entry("WAITM", Procedure, "Waits until the channels named have reached the same wait marker; the block before ends with an exact stop.", JOB_PLANNING),
    entry("WAITMC", Procedure, "Waits for a marker in the channels named, with an exact stop only if the others have not reached it yet.", JOB_PLANNING),
    entry("WAITE", Procedure, "Waits until the programs of the channels named have ended.", JOB_PLANNING),
    entry("SETM", Procedure, "Sets wait markers for coordinating channels.", JOB_PLANNING),
    entry("CLEARM", Procedure, "Clears wait markers for coordinating channels.", JOB_PLANNING),
    entry("CHANDATA", Procedure, "Selects the channel whose data the assignments after it write, in initialisation files.", JOB_PLANNING),
    entry("GETD", Procedure, "Takes an axis directly from another channel into this one (axis replacement).", JOB_PLANNING),
    // Path behaviour (Fundamentals, "Path traversing behavior"; Job Planning).
    entry("SUPA", Command, "For this block only, suppresses every work offset: settable and programmable frames, system frames, handwheel offsets, external offset and overlaid motion.", FUNDAMENTALS),
    entry("BRISK", Command, "The path axes accelerate with their full acceleration at once (no jerk limit).", JOB_PLANNING),
    entry("SOFT", Command, "The path axes accelerate with limited jerk, for smoother motion.", JOB_PLANNING),
    entry("DRIVE", Command, "The path axes accelerate with less acceleration at higher speeds (a knee-shaped characteristic).", JOB_PLANNING),
    entry("DYNNORM", Command, "The path takes the axes' standard dynamic response: the acceleration and jerk of dynamic response group 0 (MD32300, MD32431).", BASIC_FUNCTIONS),
    entry("DYNPOS", Command, "The path takes the dynamic response for positioning and tapping: group 1 of MD32300 and MD32431.", BASIC_FUNCTIONS),
    entry("DYNROUGH", Command, "The path takes the dynamic response for roughing: group 2 of MD32300 and MD32431.", BASIC_FUNCTIONS),
    entry("DYNSEMIFIN", Command, "The path takes the dynamic response for finishing: group 3 of MD32300 and MD32431.", BASIC_FUNCTIONS),
    entry("DYNFINISH", Command, "The path takes the dynamic response for smooth finishing: group 4 of MD32300 and MD32431.", BASIC_FUNCTIONS),
    entry("ACC", Command, "The acceleration of the axis or spindle named, in percent of its machine data value.", FUNDAMENTALS),
    entry("FFWON", Command, "Feedforward control on: the following error of the axes is reduced, so the path keeps closer to the contour at speed.", JOB_PLANNING),
    entry("FFWOF", Command, "Feedforward control off.", JOB_PLANNING),
    entry("CFC", Command, "The feed rate holds at the contour (the cutting edge), also on circles under tool radius compensation.", FUNDAMENTALS),
    entry("CFTCP", Command, "The feed rate holds at the tool centre point path.", FUNDAMENTALS),
    entry("CFIN", Command, "The feed rate holds at the contour for inner curves only, at the centre point path for outer ones.", FUNDAMENTALS),
    entry("FNORM", Command, "The feed value F holds over the whole block (the usual behaviour).", JOB_PLANNING),
    entry("FLIN", Command, "The feed rate changes linearly over the block from the value before to the F programmed.", JOB_PLANNING),
    entry("FCUB", Command, "The feed rate changes over the block following a cubic spline through the F values of successive blocks.", JOB_PLANNING),
    entry("ADIS", Command, "The smoothing distance for path blocks (G1, G2, G3, ...) under G641 continuous-path mode.", FUNDAMENTALS),
    entry("ADISPOS", Command, "The smoothing distance for rapid traverse blocks (G0) under G641 continuous-path mode.", FUNDAMENTALS),
    entry("RTLION", Command, "Rapid traverse G0 with linear interpolation: the axes move together on a straight line.", FUNDAMENTALS),
    entry("RTLIOF", Command, "Rapid traverse G0 without linear interpolation: each axis moves at its own rapid speed, so the path is not a straight line.", FUNDAMENTALS),
    entry("COMPON", Command, "Switches on the compressor COMPON, which joins short linear blocks into polynomials within a tolerance.", JOB_PLANNING),
    entry("COMPCURV", Command, "Switches on the compressor COMPCURV, which joins short linear blocks into polynomials with continuous curvature.", JOB_PLANNING),
    entry("COMPCAD", Command, "Switches on the compressor COMPCAD, which smooths the surface of CAM programs made of short blocks.", JOB_PLANNING),
    entry("COMPOF", Command, "Switches the NC block compressor off.", JOB_PLANNING),
    entry("CTOL", Command, "The contour tolerance for compressors and smoothing, as a length; a negative value restores the machine data's.", JOB_PLANNING),
    entry("OTOL", Command, "The orientation tolerance for compressors and orientation smoothing, as an angle in degrees; a negative value restores the machine data's.", JOB_PLANNING),
    entry("ATOL", Command, "The tolerance of the axis named for compressors and smoothing; a negative value restores the machine data's.", JOB_PLANNING),
    entry("CR", Command, "The radius of a circle programmed with G2 or G3 (a negative value for an arc over 180 degrees).", FUNDAMENTALS),
    entry("TURN", Command, "The number of additional full turns of a helix programmed with G2 or G3.", FUNDAMENTALS),
    // Splines (Job Planning, "Spline interpolation").
    entry("ASPLINE", Command, "Akima spline interpolation through the points programmed.", JOB_PLANNING),
    entry("BSPLINE", Command, "B spline interpolation: the points programmed are control points, not points on the path.", JOB_PLANNING),
    entry("CSPLINE", Command, "Cubic spline interpolation through the points programmed.", JOB_PLANNING),
    entry("BAUTO", Command, "The start of a spline is given by its next three points.", JOB_PLANNING),
    entry("BNAT", Command, "The spline starts with zero curvature (natural transition).", JOB_PLANNING),
    entry("BTAN", Command, "The spline starts tangent to the block before.", JOB_PLANNING),
    entry("EAUTO", Command, "The end of a spline is given by its last three points.", JOB_PLANNING),
    entry("ENAT", Command, "The spline ends with zero curvature (natural transition).", JOB_PLANNING),
    entry("ETAN", Command, "The spline ends tangent to the block after.", JOB_PLANNING),
    // Transformations and tool orientation (Job Planning, "Transformations").
    entry("TRAORI", Procedure, "Switches on the 4- or 5-axis transformation (the data set number given): the tool's orientation is then programmed and the rotary axes follow it.", JOB_PLANNING),
    entry("TRANSMIT", Procedure, "Switches on the TRANSMIT transformation for face machining on a turned part, the rotary axis and the transverse axis making up a Cartesian plane.", JOB_PLANNING),
    entry("TRACYL", Procedure, "Switches on the cylinder surface transformation: a contour is programmed on the unrolled cylinder surface at the working diameter given.", JOB_PLANNING),
    entry("TRAANG", Procedure, "Switches on the inclined axis transformation, for a machining axis that is not at right angles to the others.", JOB_PLANNING),
    entry("TRACON", Procedure, "Switches on a chained transformation, two transformations applied one after the other.", JOB_PLANNING),
    entry("TRAFOOF", Procedure, "Switches off every kinematic transformation of the channel.", JOB_PLANNING),
    entry("ORIWKS", Command, "The tool orientation is programmed and interpolated in the workpiece coordinate system (the default).", JOB_PLANNING),
    entry("ORIMKS", Command, "The tool orientation is programmed and interpolated in the machine coordinate system.", JOB_PLANNING),
    entry("ORIAXES", Command, "The orientation changes by linear interpolation of the rotary (or orientation) axes.", JOB_PLANNING),
    entry("ORIVECT", Command, "The orientation changes by large-circle interpolation of the tool vector (as ORIPLANE).", JOB_PLANNING),
    entry("ORIPLANE", Command, "The orientation changes in a plane, by large-circle interpolation of the tool vector (as ORIVECT).", JOB_PLANNING),
    entry("ORIEULER", Command, "A2, B2, C2 give the orientation as Euler angles.", JOB_PLANNING),
    entry("ORIRPY", Command, "A2, B2, C2 give the orientation as RPY angles (rotations in the order X, Y, Z).", JOB_PLANNING),
    entry("ORIRPY2", Command, "A2, B2, C2 give the orientation as RPY angles (rotations in the order Z, Y, X).", JOB_PLANNING),
    entry("ORIVIRT1", Command, "A2, B2, C2 give the orientation through virtual orientation axes, definition 1.", JOB_PLANNING),
    entry("ORIVIRT2", Command, "A2, B2, C2 give the orientation through virtual orientation axes, definition 2.", JOB_PLANNING),
    entry("ORICONCW", Command, "The orientation moves on the surface of a cone, clockwise.", JOB_PLANNING),
    entry("ORICONCCW", Command, "The orientation moves on the surface of a cone, counter-clockwise.", JOB_PLANNING),
    entry("ORICURVE", Command, "The orientation follows the motion of two points of the tool, each programmed as a curve.", JOB_PLANNING),
    entry("TCARR", Command, "Selects the orientable tool holder (swivel data record) with the number given; TCARR=0 deselects it.", JOB_PLANNING),
    entry("TCOABS", Command, "The tool length components are taken from the current orientation of the orientable tool holder.", JOB_PLANNING),
    entry("TCOFR", Command, "The tool length components are taken from the orientation of the active frame.", JOB_PLANNING),
    entry("TCOFRX", Command, "The tool orientation is taken from the active frame when the tool is selected, the tool pointing in the frame's X direction.", JOB_PLANNING),
    entry("TCOFRY", Command, "The tool orientation is taken from the active frame when the tool is selected, the tool pointing in the frame's Y direction.", JOB_PLANNING),
    entry("TCOFRZ", Command, "The tool orientation is taken from the active frame when the tool is selected, the tool pointing in the frame's Z direction.", JOB_PLANNING),
    entry("PAROT", Command, "Turns the workpiece coordinate system with the rotation of the tool holder's table, so it stays aligned on the workpiece.", JOB_PLANNING),
    entry("PAROTOF", Command, "Switches off the frame rotation PAROT made.", JOB_PLANNING),
    entry("TOROT", Command, "Turns the workpiece coordinate system so that its Z axis is parallel to the tool orientation, by a rotation in the system frame for TOROT ($P_TOOLFRAME).", JOB_PLANNING),
    entry("TOROTOF", Command, "Switches off the frame rotation in the tool direction that TOROT or TOFRAME made.", JOB_PLANNING),
    entry("TOFRAME", Command, "Turns the frame so that its Z axis is parallel to the tool orientation.", JOB_PLANNING),
    entry("TOFRAMEX", Command, "Turns the frame so that its X axis is parallel to the tool orientation.", JOB_PLANNING),
    entry("TOFRAMEY", Command, "Turns the frame so that its Y axis is parallel to the tool orientation.", JOB_PLANNING),
    entry("TOFRAMEZ", Command, "Turns the frame so that its Z axis is parallel to the tool orientation, as TOFRAME.", JOB_PLANNING),
    entry("CUT2D", Command, "2D tool radius compensation in the working plane (the usual kind).", JOB_PLANNING),
    // Tools and spindles (Fundamentals, "Tool offsets", "Spindle motion").
    entry("T", Command, "Selects the tool with the number or name given; whether it is changed at once or only by M6 depends on the machine data.", FUNDAMENTALS),
    entry("D", Command, "Selects the cutting edge offset (tool length and radius) with the number given for the active tool; D0 switches the offsets off.", FUNDAMENTALS),
    entry("SPOS", Command, "Moves the spindle to the angular position given, in position control; the block waits until it is reached.", FUNDAMENTALS),
    entry("SPOSA", Command, "Moves the spindle to the angular position given across block boundaries: the program goes on without waiting.", FUNDAMENTALS),
    entry("SETPIECE", Procedure, "Takes the number of workpieces given off the workpiece count of the tools on the spindle named, for tool monitoring.", JOB_PLANNING),
    entry("GETT", Function, "Returns the T number of the tool with the name and duplo number given.", JOB_PLANNING),
    entry("DELDTG", Procedure, "Deletes the distance still to go of the path or of the axis named, when the condition of a synchronized action is met.", SYNCHRONIZED_ACTIONS),
    entry("WAITP", Procedure, "Waits until the positioning axes named have reached their end positions.", FUNDAMENTALS),
    entry("WAITS", Procedure, "Waits until the spindles named have reached the positions programmed with SPOSA.", FUNDAMENTALS),
    entry("TRAILON", Procedure, "Couples a following axis to a leading axis with the factor given, so it makes the same motion (coupled motion).", JOB_PLANNING),
    entry("TRAILOF", Procedure, "Ends the coupled motion of a following axis.", JOB_PLANNING),
    // Measuring (Job Planning, "Measuring with touch-trigger probe").
    entry("MEAS", Command, "Measures with a probe during the block: the positions at the trigger are stored and the rest of the path is deleted.", JOB_PLANNING),
    entry("MEAW", Command, "Measures with a probe during the block without deleting the rest of the path.", JOB_PLANNING),
    // Language mode (Fundamentals, "List of G functions").
    entry("G290", Keyword, "Switches to the Siemens NC language (G group 47), after G291.", FUNDAMENTALS),
    entry("G291", Keyword, "Switches to the ISO dialect mode (G group 47): blocks are read as another control's G code.", FUNDAMENTALS),
    // Predefined procedures (Job Planning, "Lists": "Predefined procedures").
    entry("SETMS", Procedure, "Makes the spindle with the number given the master spindle; SETMS alone returns to the one the machine data name.", JOB_PLANNING),
    entry("SPCON", Procedure, "Switches the spindles named from speed control to position control.", JOB_PLANNING),
    entry("SPCOF", Procedure, "Switches the spindles named from position control back to speed control.", JOB_PLANNING),
    entry("ORIRESET", Procedure, "Moves the orientation axes to their initial setting: the angles given, or the machine data's for those left out.", JOB_PLANNING),
    entry("GEOAX", Procedure, "Assigns other channel axes to the geometry axes 1 to 3.", JOB_PLANNING),
    entry("FGROUP", Procedure, "Names the axes whose common path the feed rate F refers to.", JOB_PLANNING),
    entry("CTABDEF", Procedure, "Starts the definition of a curve table: the motion blocks up to CTABEND describe the following axis over the leading axis.", JOB_PLANNING),
    entry("CTABEND", Procedure, "Ends the definition of a curve table begun by CTABDEF.", JOB_PLANNING),
    entry("SOFTA", Procedure, "The axes named accelerate with limited jerk.", JOB_PLANNING),
    entry("BRISKA", Procedure, "The axes named accelerate with their full acceleration at once.", JOB_PLANNING),
    entry("DRIVEA", Procedure, "The axes named accelerate with the knee-shaped characteristic.", JOB_PLANNING),
    entry("NEWCONF", Procedure, "Makes changed machine data take effect, as activating the machine data on the operator panel does.", JOB_PLANNING),
    entry("INIT", Procedure, "Selects a program for execution in the channel named.", JOB_PLANNING),
    entry("START", Procedure, "Starts the programs selected in the channels named.", JOB_PLANNING),
    entry("MMC", Procedure, "Opens a dialog window on the operator panel from the program.", JOB_PLANNING),
    entry("DELT", Procedure, "Deletes the tool named.", JOB_PLANNING),
    entry("DELETE", Procedure, "Deletes the file named.", JOB_PLANNING),
    entry("READ", Procedure, "Reads lines of the file named into an array of strings.", JOB_PLANNING),
    entry("CORROF", Procedure, "Switches off the overlaid movements named (handwheel offsets and others).", JOB_PLANNING),
    // System variables (List Manual System Variables).
    entry("R", SystemVariable, "An R parameter, R0 to R99 by default: an arithmetic variable of type REAL that every program of the channel shares.", FUNDAMENTALS),
    entry("$P_UIFR", SystemVariable, "The settable frames of the data management by number: 0 is G500, 1 to 4 are G54 to G57, 5 onwards G505 to G599.", SYSTEM_VARIABLES),
    entry("$P_UIFRNUM", SystemVariable, "The number of the active settable frame, as `$P_UIFR` numbers them: 0 for G500, 1 to 4 for G54 to G57, 5 onwards for G505 to G599.", SYSTEM_VARIABLES),
    entry("$P_PFRAME", SystemVariable, "The programmable frame, the one TRANS, ROT, SCALE, MIRROR and their A-forms write.", SYSTEM_VARIABLES),
    entry("$P_ACTFRAME", SystemVariable, "The whole frame in force, the chain of system, basic, settable and programmable frames.", SYSTEM_VARIABLES),
    entry("$P_SETFRAME", SystemVariable, "The system frame in force for setting actual values (preset) and scratching.", SYSTEM_VARIABLES),
    entry("$P_SETFR", SystemVariable, "The system frame of the data management for setting actual values (preset) and scratching; the control's own functions write it.", SYSTEM_VARIABLES),
    entry("$P_IFRAME", SystemVariable, "The settable frame in force (the one G54 to G599 selected).", SYSTEM_VARIABLES),
    entry("$P_BFRAME", SystemVariable, "The first basic frame in force in the channel.", SYSTEM_VARIABLES),
    entry("$P_ACTBFRAME", SystemVariable, "The chain of every basic frame in force.", SYSTEM_VARIABLES),
    entry("$P_PARTFRAME", SystemVariable, "The system frame for the tool holder (TCARR and PAROT).", SYSTEM_VARIABLES),
    entry("$P_TOOLFRAME", SystemVariable, "The system frame for TOROT and TOFRAME.", SYSTEM_VARIABLES),
    entry("$P_WPFRAME", SystemVariable, "The system frame for workpiece reference points.", SYSTEM_VARIABLES),
    entry("$P_CYCFRAME", SystemVariable, "The system frame for cycles.", SYSTEM_VARIABLES),
    entry("$P_TOOLNO", SystemVariable, "The number of the active tool.", SYSTEM_VARIABLES),
    entry("$P_TOOL", SystemVariable, "The active cutting edge, its D number.", SYSTEM_VARIABLES),
    entry("$P_TOOLP", SystemVariable, "The tool number programmed last.", SYSTEM_VARIABLES),
    entry("$P_TOOLR", SystemVariable, "The active tool's radius.", SYSTEM_VARIABLES),
    entry("$P_TOOLL", SystemVariable, "The active tool's total length, by component.", SYSTEM_VARIABLES),
    entry("$P_AXN1", SystemVariable, "The name of the geometry axis that is the abscissa of the working plane.", SYSTEM_VARIABLES),
    entry("$P_AXN2", SystemVariable, "The name of the geometry axis that is the ordinate of the working plane.", SYSTEM_VARIABLES),
    entry("$P_AXN3", SystemVariable, "The name of the geometry axis that is the applicate, normal to the working plane.", SYSTEM_VARIABLES),
    entry("$P_GG", SystemVariable, "The active G function of the G group given, as its index within the group in the list of G functions.", SYSTEM_VARIABLES),
    entry("$P_SUBPAR", SystemVariable, "Whether the subprogram's parameter with the number given was written in the call (TRUE) or left to its default (FALSE).", SYSTEM_VARIABLES),
    entry("$P_F", SystemVariable, "The path feed rate programmed.", SYSTEM_VARIABLES),
    entry("$P_S", SystemVariable, "The spindle speed programmed.", SYSTEM_VARIABLES),
    entry("$P_EP", SystemVariable, "The end position programmed for an axis, in workpiece coordinates.", SYSTEM_VARIABLES),
    entry("$P_SEARCH", SystemVariable, "Whether a block search is running.", SYSTEM_VARIABLES),
    entry("$P_DRYRUN", SystemVariable, "Whether dry run feed is selected.", SYSTEM_VARIABLES),
    entry("$P_ISTEST", SystemVariable, "Whether program test is active.", SYSTEM_VARIABLES),
    entry("$PI", SystemVariable, "The circle constant pi.", SYSTEM_VARIABLES),
    entry("$AA_IM", SystemVariable, "The current position (setpoint) of an axis in machine coordinates, every axial offset included; reading it stops preprocessing.", SYSTEM_VARIABLES),
    entry("$AA_IW", SystemVariable, "The current position (setpoint) of an axis in workpiece coordinates; reading it stops preprocessing.", SYSTEM_VARIABLES),
    entry("$AA_IB", SystemVariable, "The current position (setpoint) of an axis in basic coordinates; reading it stops preprocessing.", SYSTEM_VARIABLES),
    entry("$AA_MM", SystemVariable, "The position of an axis when the probe switched, in machine coordinates.", SYSTEM_VARIABLES),
    entry("$AA_MW", SystemVariable, "The position of an axis when the probe switched, in workpiece coordinates.", SYSTEM_VARIABLES),
    entry("$AC_MEA", SystemVariable, "Whether the probe with the number given has switched (1) in the measuring block.", SYSTEM_VARIABLES),
    entry("$AC_TIME", SystemVariable, "The time since the start of the block, in seconds.", SYSTEM_VARIABLES),
    entry("$AC_MARKER", SystemVariable, "A channel's integer markers, an array a program and its synchronized actions share.", SYSTEM_VARIABLES),
    entry("$AC_PARAM", SystemVariable, "A channel's real parameters, an array a program and its synchronized actions share.", SYSTEM_VARIABLES),
    entry("$A_IN", SystemVariable, "The state of the NC's digital input with the number given.", SYSTEM_VARIABLES),
    entry("$A_OUT", SystemVariable, "The state of the NC's digital output with the number given.", SYSTEM_VARIABLES),
    entry("$A_DBB", SystemVariable, "A data byte the PLC shares with the NC, by its offset.", SYSTEM_VARIABLES),
    // Tool data (List Manual System Variables, "Tool and magazine data").
    entry("$TC_TP1", SystemVariable, "Tool data: the tool's duplo number, telling apart tools of the same name.", SYSTEM_VARIABLES),
    entry("$TC_TP2", SystemVariable, "Tool data: the tool's name.", SYSTEM_VARIABLES),
    entry("$TC_TP3", SystemVariable, "Tool data: the tool's size to the left, in half locations of the magazine.", SYSTEM_VARIABLES),
    entry("$TC_TP4", SystemVariable, "Tool data: the tool's size to the right, in half locations of the magazine.", SYSTEM_VARIABLES),
    entry("$TC_TP5", SystemVariable, "Tool data: the tool's size upwards, in half locations of the magazine.", SYSTEM_VARIABLES),
    entry("$TC_TP6", SystemVariable, "Tool data: the tool's size downwards, in half locations of the magazine.", SYSTEM_VARIABLES),
    entry("$TC_TP7", SystemVariable, "Tool data: the magazine location type the tool needs.", SYSTEM_VARIABLES),
    entry("$TC_TP8", SystemVariable, "Tool data: the tool's status, bit-coded (active, enabled, disabled, measured, ...).", SYSTEM_VARIABLES),
    entry("$TC_TP9", SystemVariable, "Tool data: the kind of tool monitoring (tool life, workpiece count, wear).", SYSTEM_VARIABLES),
    entry("$TC_TP10", SystemVariable, "Tool data: the order in which replacement tools are searched.", SYSTEM_VARIABLES),
    entry("$TC_TP11", SystemVariable, "Tool data: the tool's subgroup, for the tool search.", SYSTEM_VARIABLES),
    entry("$TC_TP_PROTA", SystemVariable, "Tool data: the name of the tool's protection zone.", SYSTEM_VARIABLES),
    entry("$TC_TP_MAX_VELO", SystemVariable, "Tool data: the tool's maximum speed.", SYSTEM_VARIABLES),
    entry("$TC_TP_MAX_ACC", SystemVariable, "Tool data: the tool's maximum acceleration.", SYSTEM_VARIABLES),
    entry("$TC_DP1", SystemVariable, "Cutting edge data: the tool type (1xx milling, 2xx drilling, 5xx turning, ...).", SYSTEM_VARIABLES),
    entry("$TC_DP2", SystemVariable, "Cutting edge data: the cutting edge position (for turning tools).", SYSTEM_VARIABLES),
    entry("$TC_DP3", SystemVariable, "Cutting edge data: geometry, length 1.", SYSTEM_VARIABLES),
    entry("$TC_DP4", SystemVariable, "Cutting edge data: geometry, length 2.", SYSTEM_VARIABLES),
    entry("$TC_DP5", SystemVariable, "Cutting edge data: geometry, length 3.", SYSTEM_VARIABLES),
    entry("$TC_DP6", SystemVariable, "Cutting edge data: geometry, radius.", SYSTEM_VARIABLES),
    entry("$TC_DP7", SystemVariable, "Cutting edge data: geometry, the corner radius of a milling tool (the slot width of a slotting saw).", SYSTEM_VARIABLES),
    entry("$TC_DP8", SystemVariable, "Cutting edge data: geometry, length 4 (the projection of a slotting saw).", SYSTEM_VARIABLES),
    entry("$TC_DP9", SystemVariable, "Cutting edge data: reserved.", SYSTEM_VARIABLES),
    entry("$TC_DP10", SystemVariable, "Cutting edge data: the angle between the tool's end face and its toroidal surface.", SYSTEM_VARIABLES),
    entry("$TC_DP11", SystemVariable, "Cutting edge data: the angle between the tool's long axis and the upper end of its toroidal surface.", SYSTEM_VARIABLES),
    entry("$TC_DP12", SystemVariable, "Cutting edge data: wear of length 1 ($TC_DP3).", SYSTEM_VARIABLES),
    entry("$TC_DP13", SystemVariable, "Cutting edge data: wear of length 2 ($TC_DP4).", SYSTEM_VARIABLES),
    entry("$TC_DP14", SystemVariable, "Cutting edge data: wear of length 3 ($TC_DP5).", SYSTEM_VARIABLES),
    entry("$TC_DP15", SystemVariable, "Cutting edge data: wear of the radius ($TC_DP6).", SYSTEM_VARIABLES),
    entry("$TC_DP16", SystemVariable, "Cutting edge data: wear of the corner radius ($TC_DP7).", SYSTEM_VARIABLES),
    entry("$TC_DP17", SystemVariable, "Cutting edge data: wear of length 4 ($TC_DP8).", SYSTEM_VARIABLES),
    entry("$TC_DP18", SystemVariable, "Cutting edge data: wear of the reserved $TC_DP9.", SYSTEM_VARIABLES),
    entry("$TC_DP19", SystemVariable, "Cutting edge data: wear of the angle $TC_DP10.", SYSTEM_VARIABLES),
    entry("$TC_DP20", SystemVariable, "Cutting edge data: wear of the angle $TC_DP11.", SYSTEM_VARIABLES),
    entry("$TC_DP21", SystemVariable, "Cutting edge data: adapter (base) dimension, length 1.", SYSTEM_VARIABLES),
    entry("$TC_DP22", SystemVariable, "Cutting edge data: adapter (base) dimension, length 2.", SYSTEM_VARIABLES),
    entry("$TC_DP23", SystemVariable, "Cutting edge data: adapter (base) dimension, length 3.", SYSTEM_VARIABLES),
    entry("$TC_DP24", SystemVariable, "Cutting edge data: the clearance angle (for turning tools).", SYSTEM_VARIABLES),
    entry("$TC_DP25", SystemVariable, "Cutting edge data: reserved.", SYSTEM_VARIABLES),
    entry("$TC_DPCE", SystemVariable, "Cutting edge data: the cutting edge number.", SYSTEM_VARIABLES),
    entry("$TC_DPH", SystemVariable, "Cutting edge data: the H number of the offset data in ISO dialect mode.", SYSTEM_VARIABLES),
    entry("$TC_DPV", SystemVariable, "Cutting edge data: the orientation of the cutting edge.", SYSTEM_VARIABLES),
    entry("$TC_DPV3", SystemVariable, "Cutting edge data: the L1 component of the cutting edge orientation.", SYSTEM_VARIABLES),
    entry("$TC_DPV4", SystemVariable, "Cutting edge data: the L2 component of the cutting edge orientation.", SYSTEM_VARIABLES),
    entry("$TC_DPV5", SystemVariable, "Cutting edge data: the L3 component of the cutting edge orientation.", SYSTEM_VARIABLES),
    entry("$TC_DPVN3", SystemVariable, "Cutting edge data: the L1 component of the orientation normal.", SYSTEM_VARIABLES),
    entry("$TC_DPVN4", SystemVariable, "Cutting edge data: the L2 component of the orientation normal.", SYSTEM_VARIABLES),
    entry("$TC_DPVN5", SystemVariable, "Cutting edge data: the L3 component of the orientation normal.", SYSTEM_VARIABLES),
    entry("$TC_DPNT", SystemVariable, "Cutting edge data: the number of teeth of the cutting edge.", SYSTEM_VARIABLES),
    entry("$TC_DPROT", SystemVariable, "Cutting edge data: the base angle of rotation of the cutting edge.", SYSTEM_VARIABLES),
    entry("$TC_MOP1", SystemVariable, "Tool monitoring: the prewarning limit of the tool life.", SYSTEM_VARIABLES),
    entry("$TC_MOP2", SystemVariable, "Tool monitoring: the tool life remaining.", SYSTEM_VARIABLES),
    entry("$TC_MOP3", SystemVariable, "Tool monitoring: the prewarning limit of the workpiece count.", SYSTEM_VARIABLES),
    entry("$TC_MOP4", SystemVariable, "Tool monitoring: the workpieces remaining.", SYSTEM_VARIABLES),
    entry("$TC_MOP5", SystemVariable, "Tool monitoring: the prewarning limit of the wear.", SYSTEM_VARIABLES),
    entry("$TC_MOP6", SystemVariable, "Tool monitoring: the wear remaining.", SYSTEM_VARIABLES),
    entry("$TC_MOP11", SystemVariable, "Tool monitoring: the tool life set.", SYSTEM_VARIABLES),
    entry("$TC_MOP13", SystemVariable, "Tool monitoring: the workpiece count set.", SYSTEM_VARIABLES),
    entry("$TC_MOP15", SystemVariable, "Tool monitoring: the wear set.", SYSTEM_VARIABLES),
    entry("$TC_MPP1", SystemVariable, "Magazine location data: the location kind (magazine location, spindle, gripper, ...).", SYSTEM_VARIABLES),
    entry("$TC_MPP2", SystemVariable, "Magazine location data: the location type, matched with the tool's $TC_TP7.", SYSTEM_VARIABLES),
    entry("$TC_MPP3", SystemVariable, "Magazine location data: whether the neighbouring locations are considered.", SYSTEM_VARIABLES),
    entry("$TC_MPP4", SystemVariable, "Magazine location data: the location's status, bit-coded.", SYSTEM_VARIABLES),
    entry("$TC_MPP5", SystemVariable, "Magazine location data: the location type index (or the wear group number).", SYSTEM_VARIABLES),
    entry("$TC_MPP6", SystemVariable, "Magazine location data: the T number of the tool in the location.", SYSTEM_VARIABLES),
    entry("$TC_MPP7", SystemVariable, "Magazine location data: the number of the tool adapter in the location.", SYSTEM_VARIABLES),
];

/// The word `name` (any case) describes, if any. An R parameter with its
/// number (`R12`) is the word `R`.
pub fn word(name: &[u8]) -> Option<&'static Word> {
    let exactly = WORDS
        .iter()
        .find(|word| word.name.as_bytes().eq_ignore_ascii_case(name));
    exactly.or_else(|| {
        is_r_parameter(name)
            .then(|| WORDS.iter().find(|word| word.name == "R"))
            .flatten()
    })
}

/// Whether `name` is an R parameter with its number (`R12`, `r0`).
pub fn is_r_parameter(name: &[u8]) -> bool {
    name.len() > 1
        && name[0].eq_ignore_ascii_case(&b'R')
        && name[1..].iter().all(u8::is_ascii_digit)
}

/// What an editor says of the word `written`: a G or M function's line
/// ([`functions::describe`]), else the table's meaning and manual, else
/// what [`functions::system_variable`] knows of a system variable (the
/// swivel data fields, the machine and setting data). `None` for a word
/// none of them describes. The cycles are [`crate::semantic::cycles`]'s.
pub fn explain(written: &[u8]) -> Option<String> {
    if let Some(function) = functions::describe(written) {
        return Some(function);
    }
    match word(written) {
        Some(word) => {
            let name = String::from_utf8_lossy(written).to_ascii_uppercase();
            Some(format!("{name}: {} ({})", word.meaning, word.manual))
        }
        None => functions::system_variable(written),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::semantic::calls::BUILTINS;
    use crate::semantic::words::FUNCTIONS;
    use crate::syntax::lexer::RESERVED;

    /// Words the lists of the language's words hold that no manual at hand
    /// describes: TRUMPF's punching commands.
    const UNDESCRIBED: &[&str] = &["PUNCH_ON", "PUNCH_OFF"];

    #[test]
    fn every_word_of_the_language_lists_is_described() {
        let lists = [RESERVED, FUNCTIONS, BUILTINS];
        let missing: Vec<&str> = lists
            .iter()
            .flat_map(|list| list.iter().copied())
            .filter(|name| !UNDESCRIBED.contains(name))
            .filter(|name| explain(name.as_bytes()).is_none())
            .collect();
        assert!(missing.is_empty(), "not described: {missing:?}");
    }

    #[test]
    fn no_word_is_described_twice() {
        let mut names: Vec<&str> = WORDS.iter().map(|word| word.name).collect();
        names.sort_unstable();
        let twice: Vec<&[&str]> = names.windows(2).filter(|w| w[0] == w[1]).collect();
        assert!(twice.is_empty(), "described twice: {twice:?}");
    }

    #[test]
    fn a_word_is_found_in_any_case() {
        let stopre = word(b"stopre").expect("STOPRE in lower case");
        assert_eq!(stopre.name, "STOPRE");
        assert_eq!(stopre.manual, JOB_PLANNING);
        assert_eq!(word(b"GoToF").map(|w| w.name), Some("GOTOF"));
        assert_eq!(word(b"$p_uifr").map(|w| w.name), Some("$P_UIFR"));
        assert_eq!(word(b"r12").map(|w| w.name), Some("R"));
        // Not words: a user's name, names that begin as an R parameter
        // does, nothing.
        for name in ["MY_SUB", "RX", "R1A", "", "$"] {
            assert!(word(name.as_bytes()).is_none(), "{name}");
        }
    }

    #[test]
    fn every_meaning_is_a_sentence_or_two() {
        for word in WORDS {
            assert!(word.meaning.ends_with('.'), "{}: no full stop", word.name);
            assert!(word.meaning.len() < 250, "{}: too long", word.name);
            assert!(
                word.meaning
                    .starts_with(|c: char| c.is_ascii_uppercase() || c.is_ascii_digit()),
                "{}: starts in lower case",
                word.name
            );
            assert!(!word.manual.is_empty(), "{}: no manual", word.name);
        }
    }

    #[test]
    fn the_g_and_m_functions_and_the_swivel_data_keep_their_own_words() {
        let explained = |word: &str| explain(word.as_bytes()).expect(word);
        assert_eq!(
            explained("g17"),
            "G17: working plane X/Y, infeed along Z (G group 6)"
        );
        assert!(explained("G290").starts_with("G290: Switches to the Siemens NC language"));
        assert!(explained("$TC_CARR9").starts_with("$TC_CARR9[m]: swivel data record m"));
        assert!(explained("stopre").starts_with("STOPRE: Stops the block preprocessing"));
        assert!(explained("R7").ends_with("(Programming Manual Fundamentals)"));
        assert_eq!(explain(b"MY_SUB"), None);
    }

    /// The vocabulary's system variables agree with the kind of word the
    /// spelling makes: `$` names are system variables and nothing else is,
    /// but for the R parameters.
    #[test]
    fn system_variables_are_the_dollar_names() {
        for word in WORDS {
            let dollar = word.name.starts_with('$');
            let system = word.kind == SystemVariable;
            assert_eq!(dollar || word.name == "R", system, "{}", word.name);
        }
    }
}
