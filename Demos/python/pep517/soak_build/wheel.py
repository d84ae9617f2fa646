"""Writes a wheel (PEP 427, PEP 491): the files, then the .dist-info folder
with METADATA, WHEEL and RECORD (each file's sha256 and size) last."""
import base64
import hashlib
import os
import time
import zipfile

from . import metadata


def _date_time():
    # Reproducible archives: SOURCE_DATE_EPOCH when set, else the zip format's first day.
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if epoch:
        return time.gmtime(max(int(epoch), 315532800))[:6]
    return (1980, 1, 1, 0, 0, 0)


def _record_hash(data: bytes) -> str:
    return "sha256=" + base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode("ascii")


class WheelWriter:
    def __init__(self, wheel_directory, tag):
        self.tag = tag
        self.name = "%s-%s-%s.whl" % (metadata.DIST_NAME, metadata.version(), tag)
        self.path = os.path.join(wheel_directory, self.name)
        self._zip = zipfile.ZipFile(self.path + ".part", "w", compression=zipfile.ZIP_DEFLATED)
        self._records = []
        self._date = _date_time()

    def add_bytes(self, arcname, data: bytes, executable=False):
        info = zipfile.ZipInfo(arcname, date_time=self._date)
        info.external_attr = (0o755 if executable else 0o644) << 16
        info.compress_type = zipfile.ZIP_DEFLATED
        self._zip.writestr(info, data)
        self._records.append("%s,%s,%d" % (arcname, _record_hash(data), len(data)))

    def add_file(self, arcname, path):
        with open(path, "rb") as f:
            self.add_bytes(arcname, f.read(), executable=os.access(path, os.X_OK))

    def finish(self):
        """Writes the .dist-info folder and returns the wheel's file name."""
        info = metadata.dist_info_name()
        self.add_bytes(info + "/METADATA", metadata.metadata_text().encode("utf-8"))
        self.add_bytes(info + "/WHEEL", metadata.wheel_text(self.tag).encode("utf-8"))
        record = "\n".join(self._records + [info + "/RECORD,,"]) + "\n"
        info_record = zipfile.ZipInfo(info + "/RECORD", date_time=self._date)
        info_record.external_attr = 0o644 << 16
        info_record.compress_type = zipfile.ZIP_DEFLATED
        self._zip.writestr(info_record, record.encode("utf-8"))
        self._zip.close()
        os.replace(self.path + ".part", self.path)
        return self.name
